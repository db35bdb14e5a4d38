// Closing an output file the CLI writes (result PLY, crease lines): one way to report a failed
// write and to leave no partial file behind.
#ifndef NVV_IO_CLOSE_OUTPUT_H
#define NVV_IO_CLOSE_OUTPUT_H

#include <sys/stat.h>

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <string>

namespace nvv {

// Closes fp; writeErrno: the first error of the writes (0: none). On failure sets `error`, removes
// the partial file (a regular file only: never /dev/...) and returns false.
inline bool CloseOutput(std::FILE* fp, int writeErrno, const std::string& path, std::string& error) {
  if (std::fclose(fp) != 0 && writeErrno == 0) writeErrno = errno ? errno : EIO;
  if (writeErrno == 0) return true;
  error = "cannot write '" + path + "': " + std::strerror(writeErrno);
  struct stat st;
  if (::stat(path.c_str(), &st) == 0 && S_ISREG(st.st_mode)) std::remove(path.c_str());
  return false;
}

}  // namespace nvv

#endif
