// The RGB8 raster: blended drawing primitives (coverage by pixel centre, no
// anti-aliasing), the built-in 5x7 font, and PNG through Debian's libstb.
#include <luxplan/output/image.h>


#include <stb_image.h>
#include <stb_image_write.h>

#include <luxplan/core/atomic_file.h>
#include <luxplan/core/error.h>

namespace luxplan {
namespace {

// The classic 5x7 LCD font for ASCII 32..126: five columns per glyph, left to right,
// bit 0 the top row.
constexpr uint8_t kFont[95][5] = {
    {0x00, 0x00, 0x00, 0x00, 0x00}, {0x00, 0x00, 0x5F, 0x00, 0x00}, {0x00, 0x07, 0x00, 0x07, 0x00},  //   ! "
    {0x14, 0x7F, 0x14, 0x7F, 0x14}, {0x24, 0x2A, 0x7F, 0x2A, 0x12}, {0x23, 0x13, 0x08, 0x64, 0x62},  // # $ %
    {0x36, 0x49, 0x55, 0x22, 0x50}, {0x00, 0x05, 0x03, 0x00, 0x00}, {0x00, 0x1C, 0x22, 0x41, 0x00},  // & ' (
    {0x00, 0x41, 0x22, 0x1C, 0x00}, {0x08, 0x2A, 0x1C, 0x2A, 0x08}, {0x08, 0x08, 0x3E, 0x08, 0x08},  // ) * +
    {0x00, 0x50, 0x30, 0x00, 0x00}, {0x08, 0x08, 0x08, 0x08, 0x08}, {0x00, 0x60, 0x60, 0x00, 0x00},  // , - .
    {0x20, 0x10, 0x08, 0x04, 0x02}, {0x3E, 0x51, 0x49, 0x45, 0x3E}, {0x00, 0x42, 0x7F, 0x40, 0x00},  // / 0 1
    {0x42, 0x61, 0x51, 0x49, 0x46}, {0x21, 0x41, 0x45, 0x4B, 0x31}, {0x18, 0x14, 0x12, 0x7F, 0x10},  // 2 3 4
    {0x27, 0x45, 0x45, 0x45, 0x39}, {0x3C, 0x4A, 0x49, 0x49, 0x30}, {0x01, 0x71, 0x09, 0x05, 0x03},  // 5 6 7
    {0x36, 0x49, 0x49, 0x49, 0x36}, {0x06, 0x49, 0x49, 0x29, 0x1E}, {0x00, 0x36, 0x36, 0x00, 0x00},  // 8 9 :
    {0x00, 0x56, 0x36, 0x00, 0x00}, {0x08, 0x14, 0x22, 0x41, 0x00}, {0x14, 0x14, 0x14, 0x14, 0x14},  // ; < =
    {0x00, 0x41, 0x22, 0x14, 0x08}, {0x02, 0x01, 0x51, 0x09, 0x06}, {0x32, 0x49, 0x79, 0x41, 0x3E},  // > ? @
    {0x7E, 0x11, 0x11, 0x11, 0x7E}, {0x7F, 0x49, 0x49, 0x49, 0x36}, {0x3E, 0x41, 0x41, 0x41, 0x22},  // A B C
    {0x7F, 0x41, 0x41, 0x22, 0x1C}, {0x7F, 0x49, 0x49, 0x49, 0x41}, {0x7F, 0x09, 0x09, 0x01, 0x01},  // D E F
    {0x3E, 0x41, 0x41, 0x51, 0x32}, {0x7F, 0x08, 0x08, 0x08, 0x7F}, {0x00, 0x41, 0x7F, 0x41, 0x00},  // G H I
    {0x20, 0x40, 0x41, 0x3F, 0x01}, {0x7F, 0x08, 0x14, 0x22, 0x41}, {0x7F, 0x40, 0x40, 0x40, 0x40},  // J K L
    {0x7F, 0x02, 0x04, 0x02, 0x7F}, {0x7F, 0x04, 0x08, 0x10, 0x7F}, {0x3E, 0x41, 0x41, 0x41, 0x3E},  // M N O
    {0x7F, 0x09, 0x09, 0x09, 0x06}, {0x3E, 0x41, 0x51, 0x21, 0x5E}, {0x7F, 0x09, 0x19, 0x29, 0x46},  // P Q R
    {0x46, 0x49, 0x49, 0x49, 0x31}, {0x01, 0x01, 0x7F, 0x01, 0x01}, {0x3F, 0x40, 0x40, 0x40, 0x3F},  // S T U
    {0x1F, 0x20, 0x40, 0x20, 0x1F}, {0x7F, 0x20, 0x18, 0x20, 0x7F}, {0x63, 0x14, 0x08, 0x14, 0x63},  // V W X
    {0x03, 0x04, 0x78, 0x04, 0x03}, {0x61, 0x51, 0x49, 0x45, 0x43}, {0x00, 0x7F, 0x41, 0x41, 0x00},  // Y Z [
    {0x02, 0x04, 0x08, 0x10, 0x20}, {0x00, 0x41, 0x41, 0x7F, 0x00}, {0x04, 0x02, 0x01, 0x02, 0x04},  // \ ] ^
    {0x40, 0x40, 0x40, 0x40, 0x40}, {0x00, 0x01, 0x02, 0x04, 0x00}, {0x20, 0x54, 0x54, 0x54, 0x78},  // _ ` a
    {0x7F, 0x48, 0x44, 0x44, 0x38}, {0x38, 0x44, 0x44, 0x44, 0x20}, {0x38, 0x44, 0x44, 0x48, 0x7F},  // b c d
    {0x38, 0x54, 0x54, 0x54, 0x18}, {0x08, 0x7E, 0x09, 0x01, 0x02}, {0x08, 0x54, 0x54, 0x54, 0x3C},  // e f g
    {0x7F, 0x08, 0x04, 0x04, 0x78}, {0x00, 0x44, 0x7D, 0x40, 0x00}, {0x20, 0x40, 0x44, 0x3D, 0x00},  // h i j
    {0x7F, 0x10, 0x28, 0x44, 0x00}, {0x00, 0x41, 0x7F, 0x40, 0x00}, {0x7C, 0x04, 0x18, 0x04, 0x78},  // k l m
    {0x7C, 0x08, 0x04, 0x04, 0x78}, {0x38, 0x44, 0x44, 0x44, 0x38}, {0x7C, 0x14, 0x14, 0x14, 0x08},  // n o p
    {0x08, 0x14, 0x14, 0x18, 0x7C}, {0x7C, 0x08, 0x04, 0x04, 0x08}, {0x48, 0x54, 0x54, 0x54, 0x20},  // q r s
    {0x04, 0x3F, 0x44, 0x40, 0x20}, {0x3C, 0x40, 0x40, 0x20, 0x7C}, {0x1C, 0x20, 0x40, 0x20, 0x1C},  // t u v
    {0x3C, 0x40, 0x30, 0x40, 0x3C}, {0x44, 0x28, 0x10, 0x28, 0x44}, {0x0C, 0x50, 0x50, 0x50, 0x3C},  // w x y
    {0x44, 0x64, 0x54, 0x4C, 0x44}, {0x00, 0x08, 0x36, 0x41, 0x00}, {0x00, 0x00, 0x7F, 0x00, 0x00},  // z { |
    {0x00, 0x41, 0x36, 0x08, 0x00}, {0x08, 0x04, 0x08, 0x10, 0x08},                                  // } ~
};

const uint8_t* glyph(char c) {
    unsigned u = static_cast<unsigned char>(c);
    if (u < 32 || u > 126) u = '?';
    return kFont[u - 32];
}

uint8_t blendChannel(uint8_t dst, uint8_t src, double alpha) {
    return uint8_t(std::lround(dst + (double(src) - dst) * alpha));
}

// Squared distance from p to the segment ab.
double segmentDistanceSquared(Vec2 p, Vec2 a, Vec2 b) {
    Vec2 ab = b - a, ap = p - a;
    double len2 = dot(ab, ab);
    double t = len2 > 0 ? std::clamp(dot(ap, ab) / len2, 0.0, 1.0) : 0.0;
    Vec2 d = ap - ab * t;
    return dot(d, d);
}

// Pixel range [lo, hi) whose centres may lie in [a, b], clipped to [0, n).
std::pair<int, int> pixelSpan(double a, double b, int n) {
    int lo = std::max(0, int(std::floor(a - 0.5)));
    int hi = std::min(n, int(std::ceil(b + 0.5)));
    return {lo, hi};
}

void appendBytes(void* context, void* data, int size) {
    auto* out = static_cast<std::vector<uint8_t>*>(context);
    const auto* bytes = static_cast<const uint8_t*>(data);
    out->insert(out->end(), bytes, bytes + size);
}

}  // namespace

Rgb mix(Rgb a, Rgb b, double t) {
    t = std::clamp(t, 0.0, 1.0);
    return {blendChannel(a.r, b.r, t), blendChannel(a.g, b.g, t), blendChannel(a.b, b.b, t)};
}

Image::Image(int width, int height, Rgb fill)
    : width_(std::max(0, width)), height_(std::max(0, height)), pixels_(size_t(width_) * size_t(height_), fill) {}

void Image::fill(Rgb color) { std::fill(pixels_.begin(), pixels_.end(), color); }

void Image::blendPixel(int x, int y, Rgb color, double alpha) {
    if (x < 0 || y < 0 || x >= width_ || y >= height_ || alpha <= 0) return;
    Rgb& p = at(x, y);
    p = alpha >= 1 ? color : mix(p, color, alpha);
}

void Image::fillRect(double x0, double y0, double x1, double y1, Rgb color, double alpha) {
    if (x0 > x1) std::swap(x0, x1);
    if (y0 > y1) std::swap(y0, y1);
    int xa = std::max(0, int(std::ceil(x0 - 0.5))), xb = std::min(width_, int(std::ceil(x1 - 0.5)));
    int ya = std::max(0, int(std::ceil(y0 - 0.5))), yb = std::min(height_, int(std::ceil(y1 - 0.5)));
    for (int y = ya; y < yb; ++y)
        for (int x = xa; x < xb; ++x) blendPixel(x, y, color, alpha);
}

void Image::drawRect(double x0, double y0, double x1, double y1, Rgb color, double thickness, double alpha) {
    drawPolygon({{x0, y0}, {x1, y0}, {x1, y1}, {x0, y1}}, color, thickness, alpha);
}

void Image::drawLine(Vec2 a, Vec2 b, Rgb color, double thickness, double alpha) {
    double r = std::max(thickness, 1.0) / 2 + 1e-6, r2 = r * r;
    auto [xa, xb] = pixelSpan(std::min(a.x, b.x) - r, std::max(a.x, b.x) + r, width_);
    auto [ya, yb] = pixelSpan(std::min(a.y, b.y) - r, std::max(a.y, b.y) + r, height_);
    for (int y = ya; y < yb; ++y)
        for (int x = xa; x < xb; ++x)
            if (segmentDistanceSquared({x + 0.5, y + 0.5}, a, b) <= r2) blendPixel(x, y, color, alpha);
}

void Image::fillPolygon(const std::vector<Vec2>& points, Rgb color, double alpha) {
    if (points.size() < 3) return;
    double ylo = kInf, yhi = -kInf;
    for (Vec2 p : points) ylo = std::min(ylo, p.y), yhi = std::max(yhi, p.y);
    auto [ya, yb] = pixelSpan(ylo, yhi, height_);
    std::vector<double> crossings;
    for (int y = ya; y < yb; ++y) {
        double yc = y + 0.5;
        crossings.clear();
        for (size_t i = 0; i < points.size(); ++i) {
            Vec2 p = points[i], q = points[(i + 1) % points.size()];
            if ((p.y <= yc) != (q.y <= yc)) crossings.push_back(p.x + (yc - p.y) / (q.y - p.y) * (q.x - p.x));
        }
        std::sort(crossings.begin(), crossings.end());
        for (size_t k = 0; k + 1 < crossings.size(); k += 2) {
            int xa = std::max(0, int(std::ceil(crossings[k] - 0.5)));
            int xb = std::min(width_, int(std::ceil(crossings[k + 1] - 0.5)));
            for (int x = xa; x < xb; ++x) blendPixel(x, y, color, alpha);
        }
    }
}

void Image::drawPolygon(const std::vector<Vec2>& points, Rgb color, double thickness, double alpha) {
    if (points.empty()) return;
    double r = std::max(thickness, 1.0) / 2 + 1e-6, r2 = r * r;
    Bounds3 box;
    for (Vec2 p : points) box.extend(Vec3(p.x, p.y, 0));
    auto [xa, xb] = pixelSpan(box.lo.x - r, box.hi.x + r, width_);
    auto [ya, yb] = pixelSpan(box.lo.y - r, box.hi.y + r, height_);
    const size_t n = points.size();
    // One test per pixel against every edge, so that corners are blended once.
    for (int y = ya; y < yb; ++y)
        for (int x = xa; x < xb; ++x) {
            Vec2 c{x + 0.5, y + 0.5};
            for (size_t i = 0; i < n; ++i)
                if (segmentDistanceSquared(c, points[i], points[(i + 1) % n]) <= r2) {
                    blendPixel(x, y, color, alpha);
                    break;
                }
        }
}

void Image::fillCircle(Vec2 center, double radius, Rgb color, double alpha) {
    double r2 = radius * radius;
    auto [xa, xb] = pixelSpan(center.x - radius, center.x + radius, width_);
    auto [ya, yb] = pixelSpan(center.y - radius, center.y + radius, height_);
    for (int y = ya; y < yb; ++y)
        for (int x = xa; x < xb; ++x) {
            double dx = x + 0.5 - center.x, dy = y + 0.5 - center.y;
            if (dx * dx + dy * dy <= r2) blendPixel(x, y, color, alpha);
        }
}

void Image::drawCircle(Vec2 center, double radius, Rgb color, double thickness, double alpha) {
    double h = std::max(thickness, 1.0) / 2, outer = radius + h;
    auto [xa, xb] = pixelSpan(center.x - outer, center.x + outer, width_);
    auto [ya, yb] = pixelSpan(center.y - outer, center.y + outer, height_);
    for (int y = ya; y < yb; ++y)
        for (int x = xa; x < xb; ++x) {
            double d = std::hypot(x + 0.5 - center.x, y + 0.5 - center.y);
            if (std::abs(d - radius) <= h) blendPixel(x, y, color, alpha);
        }
}

int textWidth(std::string_view text, int scale) {
    int widest = 0, current = 0;
    for (char c : text) {
        if (c == '\n') {
            widest = std::max(widest, current);
            current = 0;
        } else {
            ++current;
        }
    }
    widest = std::max(widest, current);
    return widest > 0 ? (widest * kGlyphAdvance - 1) * scale : 0;
}

int textHeight(std::string_view text, int scale) {
    int lines = 1 + int(std::count(text.begin(), text.end(), '\n'));
    return ((lines - 1) * kLineAdvance + kGlyphHeight) * scale;
}

void Image::drawText(double x, double y, std::string_view text, Rgb color, int scale, TextAlign align, double alpha) {
    scale = std::max(1, scale);
    double lineY = y;
    size_t start = 0;
    while (start <= text.size()) {
        size_t end = text.find('\n', start);
        if (end == std::string_view::npos) end = text.size();
        std::string_view line = text.substr(start, end - start);
        int w = textWidth(line, scale);
        double left = align == TextAlign::Left ? x : align == TextAlign::Center ? x - w / 2.0 : x - w;
        left = std::round(left);
        for (size_t i = 0; i < line.size(); ++i) {
            const uint8_t* g = glyph(line[i]);
            double gx = left + double(i) * kGlyphAdvance * scale;
            for (int col = 0; col < kGlyphWidth; ++col)
                for (int row = 0; row < kGlyphHeight; ++row)
                    if (g[col] >> row & 1)
                        fillRect(gx + col * scale, lineY + row * scale, gx + (col + 1) * scale,
                                 lineY + (row + 1) * scale, color, alpha);
        }
        lineY += kLineAdvance * scale;
        start = end + 1;
    }
}

void Image::blit(const Image& source, int x, int y) {
    for (int sy = 0; sy < source.height(); ++sy) {
        int ty = y + sy;
        if (ty < 0 || ty >= height_) continue;
        for (int sx = 0; sx < source.width(); ++sx) {
            int tx = x + sx;
            if (tx >= 0 && tx < width_) at(tx, ty) = source.at(sx, sy);
        }
    }
}

std::vector<uint8_t> encodePng(const Image& image) {
    std::vector<uint8_t> bytes;
    if (image.empty()) throw IoError("cannot encode an empty image as PNG");
    static_assert(sizeof(Rgb) == 3, "Rgb must be three packed bytes");
    int ok = stbi_write_png_to_func(appendBytes, &bytes, image.width(), image.height(), 3, image.pixels().data(),
                                    image.width() * 3);
    if (!ok) throw IoError("PNG encoding failed");
    return bytes;
}

void writePng(const Image& image, const std::filesystem::path& file) {
    std::vector<uint8_t> bytes = encodePng(image);
    writeFileAtomically(file, std::string_view(reinterpret_cast<const char*>(bytes.data()), bytes.size()));
}

Image readPng(const std::filesystem::path& file) {
    int w = 0, h = 0, channels = 0;
    unsigned char* data = stbi_load(file.string().c_str(), &w, &h, &channels, 3);
    if (!data) {
        const char* reason = stbi_failure_reason();
        throw IoError(file.string() + ": cannot read image (" + (reason ? reason : "unknown error") + ")");
    }
    Image image(w, h);
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x) {
            const unsigned char* p = data + (size_t(y) * size_t(w) + size_t(x)) * 3;
            image.at(x, y) = {p[0], p[1], p[2]};
        }
    stbi_image_free(data);
    return image;
}

}  // namespace luxplan
