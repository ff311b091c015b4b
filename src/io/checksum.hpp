// A file's checksum, to tell whether it changed between two runs (a rebuilt executable, an edited
// study file), not to guard against tampering: FNV-1a of 64 bits, which fits in a few lines and
// needs no library.
#pragma once

#include <string>

namespace dlpverify {

// 16 hexadecimal digits of the FNV-1a 64 hash of the file's bytes; "unknown" when it cannot be read.
std::string file_checksum(const std::string& path);

}  // namespace dlpverify
