#pragma once
#include <filesystem>
#include <string>

namespace sg {

// The whole file as bytes. Throws sg::Error naming the file when it cannot be
// read, is a directory, or holds more than `max_bytes` (the limit for `kind`
// files, e.g. "scheme", named in the message); it never reads more than
// max_bytes + 1 bytes, whatever the file claims to be (a pipe, /dev/zero).
std::string read_file(const std::filesystem::path& path, long max_bytes, const std::string& kind);

}  // namespace sg
