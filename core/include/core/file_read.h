#pragma once
// Reading a file a user named, whole, without hanging or exhausting memory (issue 12
// point 2): a FIFO would block open() forever, /dev/zero or /dev/urandom never end, and
// a directory "opens" on some systems. Only regular files are read: the path is
// stat()ed before open (no open of a FIFO at all), opened with O_NONBLOCK and fstat()ed
// again (the path may have been swapped in between), and at most `maxBytes` are read.
#include <cstddef>
#include <string>

namespace wb {

// Reads the regular file `path` into `out`. On failure returns false and sets `error`
// to "PATH: problem" (cannot open: strerror; is a directory; not a regular file (a FIFO,
// device or socket); larger than the limit, in MB or bytes).
bool readRegularFile(const std::string& path, std::size_t maxBytes, std::string& out,
                     std::string& error);

// Text of a byte string for a message: printable ASCII as is, every other byte as \xNN
// (no raw escape sequence or NUL reaches a terminal), cut after `maxChars` bytes of
// input with "..." so a megabyte-long token is not echoed whole.
std::string escapeForMessage(const std::string& bytes, std::size_t maxChars = 40);

} // namespace wb
