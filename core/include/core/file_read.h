#pragma once
// Reading a file a user named, whole, without hanging or exhausting memory (issue 12
// point 2): a FIFO would block open() forever, /dev/zero or /dev/urandom never end, and
// a directory "opens" on some systems. Only regular files are read: the path is
// stat()ed before open (no open of a FIFO at all), opened with O_NONBLOCK and fstat()ed
// again (the path may have been swapped in between), and at most `maxBytes` are read.
#include <cstddef>
#include <string>
#include <string_view>

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

// Output files (issue 20 points 1 and 11): the same rule for every program that writes
// one (PNG, NFF, a lab's --out and --screenshot). Checked without opening anything:
//  - an existing regular file is replaced; a new name in an existing directory is created;
//  - a directory, FIFO, device or socket is refused (a FIFO would block open() forever,
//    /dev/full swallowed the write, a device is not a picture file);
//  - a symbolic link is followed to the file it names (that file is written, the link
//    stays); a dangling link, a loop or a chain of more than 40 links is refused, naming
//    the problem, instead of being replaced by a regular file.
// On success `target` is the path to write (the link's target, or `path` itself). On
// failure `error` is "PATH: problem" with PATH escaped (escapeForMessage).
bool checkOutputFile(const std::string& path, std::string& target, std::string& error);

// The line (1-based; lines end at LF, CR LF or CR) of the first NUL byte in `text`, or 0
// when it has none: one memchr, so a 500 MB binary file is refused before it is split
// into lines (issue 20 point 16: the NFF reader copied it whole as one token first).
int firstNulLine(std::string_view text);
// The message both scene readers give for it.
const char* nulByteMessage();

} // namespace wb
