#pragma once

#include <string>

namespace areagraph {

// What some editors and spreadsheets put before UTF-8 text; no part of it.
inline constexpr char kUtf8ByteOrderMark[] = "\xEF\xBB\xBF";

// What the file system entry at `path` is when it is not a regular file or
// a folder ("a FIFO (named pipe)", "a character device", "a block device",
// "a socket"); "" for a regular file, a folder or nothing there. Links are
// followed.
std::string SpecialFileKind(const std::string& path);

// The bytes of the regular file `path`, at most `max_bytes` of them. The
// file is opened without blocking and checked before it is read, so that a
// FIFO without a writer or a device is refused at once instead of hanging
// the tool. `what` names the file in messages ("options file 'o.pbtxt'").
// Throws InputError "cannot read <what>: <reason>", the reason one of "it
// does not exist", "it is a directory", "it is a FIFO (named pipe), not a
// regular file" (or another special file), "its name holds a NUL byte" or
// the system's ("permission denied").
std::string ReadInputFile(const std::string& path, const std::string& what,
                          size_t max_bytes = static_cast<size_t>(-1));

}  // namespace areagraph
