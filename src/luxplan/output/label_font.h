// The plan's labels in a real typeface: DejaVu Sans (Debian's fonts-dejavu-core,
// installed by scripts/install-deps.sh) rasterized by stb_truetype, anti-aliased, at
// a height in pixels. Where the font file cannot be read, the built-in 5x7 bitmap font
// (image.h) at twice its size stands in, with one warning on stderr.
#pragma once

#include <filesystem>
#include <string_view>

#include <luxplan/output/image.h>

namespace luxplan {

// The font file: $LUXPLAN_FONT if set, else DejaVu Sans where Debian installs it.
std::filesystem::path labelFontFile();

class LabelFont {
public:
    // Text whose lines are `pixelHeight` pixels apart (ascent plus descent).
    explicit LabelFont(double pixelHeight = 14);

    // Width (the widest line) and height (lines x line height) in pixels, rounded up.
    int width(std::string_view text) const;
    int height(std::string_view text) const;
    // The text with the top of its first line at y; (x: its left end, centre or right
    // end by `align`). UTF-8; '\n' starts a new line.
    void draw(Image& image, double x, double y, std::string_view text, Rgb color,
              TextAlign align = TextAlign::Left, double alpha = 1) const;

private:
    double lineWidth(std::string_view line) const;
    bool trueType_ = false;
    double pixelHeight_ = 14;
    double scale_ = 1;      // font units to pixels
    double ascent_ = 0;     // pixels above the baseline
    double lineHeight_ = 0; // pixels between lines
    int bitmapScale_ = 2;
};

}  // namespace luxplan
