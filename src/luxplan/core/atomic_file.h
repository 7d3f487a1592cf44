// Output files that are whole or absent: written to a temporary name in the same
// folder, flushed to disk, then renamed over the target (rename is atomic on POSIX),
// so a crash, a kill or a full disk never leaves a half-written file.
#pragma once

#include <filesystem>
#include <string_view>

namespace luxplan {

// Throws IoError naming the file (and the system's reason: "No space left on device")
// if any step fails; the temporary file is then removed.
void writeFileAtomically(const std::filesystem::path& file, std::string_view bytes);

}  // namespace luxplan
