#include <luxplan/io/photometry_io.h>

#include <algorithm>
#include <cctype>
#include <fstream>
#include <sstream>

#include <luxplan/core/error.h>
#include <luxplan/core/limits.h>
#include <luxplan/json/fields.h>

namespace luxplan::io {

std::shared_ptr<const IntensityDistribution> loadPhotometry(const std::filesystem::path& file) {
    const std::string name = file.string();
    std::string ext = file.extension().string();
    std::transform(ext.begin(), ext.end(), ext.begin(), [](unsigned char c) { return char(std::tolower(c)); });
    if (ext != ".ies" && ext != ".ldt")
        throw IoError(name + ": unsupported photometry format \"" + ext + "\" (use .ies or .ldt)");
    std::error_code ec;
    if (!std::filesystem::exists(file, ec)) throw IoError(name + ": no such file");
    // Never opened otherwise: a FIFO would block, a device such as /dev/zero never end.
    if (!std::filesystem::is_regular_file(file, ec))
        throw IoError(name + ": not a regular file (a folder, FIFO or device cannot be read)");
    if (auto size = std::filesystem::file_size(file, ec); !ec && size > limits::kMaxPhotometryFileBytes)
        throw IoError(name + ": file of " + std::to_string(size) + " bytes exceeds the limit of " +
                      std::to_string(limits::kMaxPhotometryFileBytes) + " bytes");
    std::ifstream in(file, std::ios::binary);
    if (!in) throw IoError(name + ": cannot open the file");
    std::stringstream buffer;
    buffer << in.rdbuf();
    PhotometricTable table = ext == ".ies" ? readIes(buffer.str(), name) : readEulumdat(buffer.str(), name);
    auto d = std::make_shared<const IntensityDistribution>(table);
    if (!(d->flux() > 0)) throw IoError(name + ": the distribution emits no light (every intensity is 0)");
    // "flux_lm" scales the distribution by flux_lm / its own flux: a bound of the cost C.
    if (d->flux() < limits::kMinPhotometryFluxLm)
        throw IoError(name + ": the distribution's flux of " + json::formatNumber(d->flux()) +
                      " lm is below the limit of " + json::formatNumber(limits::kMinPhotometryFluxLm) + " lm");
    return d;
}

}  // namespace luxplan::io
