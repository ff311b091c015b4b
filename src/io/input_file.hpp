// Reading a file the user named as an input: a regular file of bounded size, whoever opens it.
//
// The path is opened without blocking (O_NONBLOCK: a FIFO with no writer does not hang the open)
// and checked after opening, on the descriptor itself (fstat), so what is read is what was
// checked: a FIFO, a device, a socket or a folder is refused, and so is a file larger than the
// limit for its kind (a link to /dev/zero is a device; a huge file is refused before a byte is
// read). docs/cli.md, "What a path may name", lists the limits.
#pragma once

#include <cstdint>
#include <fstream>
#include <string>

namespace dlpverify {

/// The largest input of each kind, in bytes (docs/cli.md states them).
namespace input_limit {
inline constexpr std::uintmax_t study_file = 1u << 20;       ///< a study file (TOML): 1 MiB
inline constexpr std::uintmax_t tableau = 1u << 20;          ///< a Butcher tableau (TOML): 1 MiB
inline constexpr std::uintmax_t variables = 1u << 20;        ///< an analyze variables file: 1 MiB
inline constexpr std::uintmax_t result = 256u << 20;         ///< a study's JSON (baseline, plot, compare): 256 MiB
inline constexpr std::uintmax_t journal = 256u << 20;        ///< a study's journal: 256 MiB
inline constexpr std::uintmax_t run = std::uintmax_t{64} << 30;  ///< a run or exchange file (HDF5, CSV): 64 GiB
}  // namespace input_limit

/// The regular file at `path` (links followed) opened read-only, checked on its descriptor:
/// throws InputError(`kind`, path, reason) when it does not exist, cannot be opened, is not a
/// regular file (FIFO, device, socket, folder) or is larger than `limit` bytes. The descriptor
/// is blocking again and close-on-exec; the caller owns it.
int open_input_file(const std::string& kind, const std::string& path, std::uintmax_t limit);

/// The whole of the regular file at `path`, checked as open_input_file does; a file that grows
/// past `limit` while it is read is refused too.
std::string read_input_file(const std::string& kind, const std::string& path, std::uintmax_t limit);

/// A stream on the regular file at `path`, checked as open_input_file does, for a reader too
/// large to hold in memory at once: the stream reads the very file that was checked (it is
/// opened through the checked descriptor's /proc/self/fd entry).
std::ifstream open_input_stream(const std::string& kind, const std::string& path, std::uintmax_t limit);

/// Checks `path` as open_input_file does and closes it again: for a file a library opens by
/// its name (HDF5). The file is checked, not held: a path swapped in between is the caller's
/// risk, as for any file named twice.
void check_input_file(const std::string& kind, const std::string& path, std::uintmax_t limit);

}  // namespace dlpverify
