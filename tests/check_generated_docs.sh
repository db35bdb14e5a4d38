#!/usr/bin/env bash
# The README's parameter table and default .mlx, and docs/cli.md's --help, are what the parameter
# table generates.
# Usage: check_generated_docs.sh NVV_DOCGEN REPO
set -euo pipefail
docgen=$1 repo=$2
"$docgen" --check "$repo/README.md"
"$docgen" --check "$repo/docs/cli.md"
grep -q '<!-- generated:parameters -->' "$repo/README.md" || { echo "README.md has no generated parameter table"; exit 1; }
grep -q '<!-- generated:mlx -->' "$repo/README.md" || { echo "README.md has no generated .mlx"; exit 1; }
grep -q '<!-- generated:help -->' "$repo/docs/cli.md" || { echo "docs/cli.md has no generated --help"; exit 1; }
echo "README.md and docs/cli.md match the parameter table"
