// Standard output is an output like any file: what a run prints there (the console table, a
// result sent to `-`) that cannot be written is exit 4, never a silent success.
#pragma once

namespace dlpverify {

/// Throws OutputError when standard output is closed as the program starts: anything the run
/// printed would be lost, and the first file it opened would take its place.
void require_open_standard_output();

/// Flushes standard output; throws OutputError naming the reason when it could not be written
/// (a full disk, /dev/full, an error of the device).
void check_standard_output();

}  // namespace dlpverify
