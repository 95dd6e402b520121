#pragma once

// The one way the tools write a file that the user names (ag-export --out,
// ag-render --out, ag-eval --gt-picture, the example-map generators) and
// check their standard output, so that nothing is half written, nothing that
// is not a plain file is replaced, and every failure says why.

#include <string>
#include <string_view>

namespace areagraph {

// The --out name that means standard output.
inline constexpr char kStandardOutputName[] = "-";

// True for "-".
bool IsStandardOutput(const std::string& target);

// Writes `bytes` to `target`, chosen by what `target` is:
// - "-": standard output.
// - a new path or a regular file: a temporary file in the same folder is
//   written, flushed to disk and renamed into place, so readers see the old
//   file or the new one and a failure leaves the old one; a replaced file
//   keeps its permission bits. A read-only file is refused, as the shell's
//   `>` would.
// - a symbolic link: followed; its target is written by these rules and the
//   link stays a link.
// - a FIFO or a character device (a pipe, /dev/null, /dev/tty, /dev/stdout):
//   written into as it is, never replaced.
// - a folder, a block device, a socket or a link to nothing: refused.
// - a store this process opened, or its -wal, -shm or -journal file, by any
//   name (common/protected_files.h): refused, since it would destroy the store.
// Every write, flush and close is checked. Throws InputError
// "cannot write '<target>': <reason>", the reason in words from errno
// ("no space left on device").
void WriteOutputFile(const std::string& target, std::string_view bytes);

// Flushes standard output and throws Error("cannot write to standard output:
// <reason>") when anything written to it was lost (a full disk behind
// `> file`, a closed descriptor). RunCommand calls it after every tool.
void FlushStandardOutput();

// strerror(code) starting in lower case, to follow "cannot ...: ".
std::string ErrnoText(int code);

}  // namespace areagraph
