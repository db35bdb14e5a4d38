# Sourced by the test scripts: what AddressSanitizer and UBSan do on a finding. Any report ends
# the program with a non-zero status, so the test that ran it fails.
export ASAN_OPTIONS=abort_on_error=1:detect_leaks=1:strict_string_checks=1:detect_stack_use_after_return=1
export UBSAN_OPTIONS=print_stacktrace=1:halt_on_error=1
export LSAN_OPTIONS=suppressions=$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)/lsan.supp:print_suppressions=0
# The malformed corpus bounds each case to tell a hang from work; sanitized code runs up to ten
# times slower (the 100,000-valence fan takes about 400 s under ASan).
export NVV_CORPUS_SECONDS=900
