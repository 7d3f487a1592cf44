// An 8-bit RGB raster with the few drawing primitives the output pictures need
// (blended rectangles, thick lines, polygons, circles, a built-in 5x7 bitmap font)
// and PNG encoding/decoding through stb.
#pragma once

#include <cstdint>
#include <filesystem>
#include <string>
#include <string_view>
#include <vector>

#include <luxplan/core/math.h>

namespace luxplan {

struct Rgb {
    uint8_t r = 0, g = 0, b = 0;
    constexpr bool operator==(const Rgb&) const = default;
};

inline constexpr Rgb kBlack{0, 0, 0};
inline constexpr Rgb kWhite{255, 255, 255};

// Linear interpolation between two colours, t in [0, 1].
Rgb mix(Rgb a, Rgb b, double t);

enum class TextAlign { Left, Center, Right };

// Pixel coordinates: origin at the top-left pixel's corner, x right, y down; pixel
// (x, y) covers [x, x + 1) x [y, y + 1) and is hit when its centre is covered.
// Every primitive clips to the image and blends with opacity `alpha` in [0, 1].
class Image {
public:
    Image() = default;
    Image(int width, int height, Rgb fill = kWhite);

    int width() const { return width_; }
    int height() const { return height_; }
    bool empty() const { return pixels_.empty(); }
    Rgb& at(int x, int y) { return pixels_[size_t(y) * size_t(width_) + size_t(x)]; }
    const Rgb& at(int x, int y) const { return pixels_[size_t(y) * size_t(width_) + size_t(x)]; }
    const std::vector<Rgb>& pixels() const { return pixels_; }  // row-major, top row first

    void fill(Rgb color);
    void blendPixel(int x, int y, Rgb color, double alpha = 1);
    // The pixels whose centres lie in [x0, x1) x [y0, y1).
    void fillRect(double x0, double y0, double x1, double y1, Rgb color, double alpha = 1);
    void drawRect(double x0, double y0, double x1, double y1, Rgb color, double thickness = 1, double alpha = 1);
    // A segment `thickness` pixels wide with round caps.
    void drawLine(Vec2 a, Vec2 b, Rgb color, double thickness = 1, double alpha = 1);
    // Even-odd fill of a simple or self-intersecting polygon; each pixel blended once.
    void fillPolygon(const std::vector<Vec2>& points, Rgb color, double alpha = 1);
    // The closed outline of a polygon.
    void drawPolygon(const std::vector<Vec2>& points, Rgb color, double thickness = 1, double alpha = 1);
    void fillCircle(Vec2 center, double radius, Rgb color, double alpha = 1);
    void drawCircle(Vec2 center, double radius, Rgb color, double thickness = 1, double alpha = 1);
    // Text in the built-in 5x7 font (printable ASCII; anything else drawn as '?'),
    // each font pixel `scale` x `scale` image pixels; (x, y) is the top of the line at
    // the left end, centre or right end by `align`. '\n' starts a new line.
    void drawText(double x, double y, std::string_view text, Rgb color, int scale = 1,
                  TextAlign align = TextAlign::Left, double alpha = 1);
    // Copies `source` with its top-left corner at (x, y), clipped.
    void blit(const Image& source, int x, int y);

private:
    int width_ = 0, height_ = 0;
    std::vector<Rgb> pixels_;
};

// Size in pixels of a text in the built-in font (the widest line; line count x line height).
int textWidth(std::string_view text, int scale = 1);
int textHeight(std::string_view text, int scale = 1);
inline constexpr int kGlyphWidth = 5, kGlyphHeight = 7, kGlyphAdvance = 6, kLineAdvance = 9;  // font pixels

// PNG bytes of the image (for embedding, e.g. base64 in HTML).
std::vector<uint8_t> encodePng(const Image& image);
// Writes a PNG file; throws IoError when it cannot be written.
void writePng(const Image& image, const std::filesystem::path& file);
// Reads any 8-bit image stb understands as RGB; throws IoError on failure.
Image readPng(const std::filesystem::path& file);

}  // namespace luxplan
