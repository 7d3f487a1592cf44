// Reads luminaires' photometric files, type C: IES LM-63 (.ies; LM-63-1995, -2002,
// -2019, also IESNA91 and the headerless 1986 form) and EULUMDAT (.ldt, ISO-8859-1,
// decimal commas tolerated). Every problem is an IoError whose message reads
// "FILE:LINE: message" (FILE as the caller names it), or "FILE: message" when no
// line is to blame.
#pragma once

#include <filesystem>
#include <memory>
#include <string>

#include <luxplan/emitters/intensity_distribution.h>

namespace luxplan::io {

// The distribution of a .ies or .ldt file, chosen by its extension (any case).
std::shared_ptr<const IntensityDistribution> loadPhotometry(const std::filesystem::path& file);

// The table a file's text holds, candela already multiplied by the file's factors
// (ies_reader.cpp, eulumdat_reader.cpp); `name` is FILE in messages.
PhotometricTable readIes(const std::string& text, const std::string& name);
PhotometricTable readEulumdat(const std::string& text, const std::string& name);

}  // namespace luxplan::io
