// LabelFont: stb_truetype over one font file read once per process.
#include <luxplan/output/label_font.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <fstream>
#include <iostream>
#include <iterator>
#include <vector>

#include <stb_truetype.h>  // the implementation is in Debian's libstb

namespace luxplan {
namespace {

constexpr const char* kDejaVuSans = "/usr/share/fonts/truetype/dejavu/DejaVuSans.ttf";

// The font file's bytes and stb's view of them, or nothing (then a warning, once).
struct LoadedLabelFont {
    std::vector<unsigned char> bytes;
    stbtt_fontinfo info{};
    bool ok = false;
};

const LoadedLabelFont& loadedLabelFont() {
    static const LoadedLabelFont font = [] {
        LoadedLabelFont f;
        const std::filesystem::path file = labelFontFile();
        std::ifstream in(file, std::ios::binary);
        if (in) f.bytes.assign(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
        if (!f.bytes.empty()) {
            const int offset = stbtt_GetFontOffsetForIndex(f.bytes.data(), 0);
            f.ok = offset >= 0 && stbtt_InitFont(&f.info, f.bytes.data(), offset) != 0;
        }
        if (!f.ok)
            std::cerr << "luxplan: warning: cannot read the labels' font " << file.string()
                      << " (install fonts-dejavu-core, or set LUXPLAN_FONT to a .ttf file): the plan's labels are "
                         "drawn in the built-in bitmap font\n";
        return f;
    }();
    return font;
}

// The next code point of UTF-8 text at `i` (advanced past it); '?' for a broken sequence.
int nextCodePoint(std::string_view text, size_t& i) {
    const unsigned char c = static_cast<unsigned char>(text[i++]);
    if (c < 0x80) return c;
    const int extra = c >= 0xf0 ? 3 : c >= 0xe0 ? 2 : c >= 0xc0 ? 1 : -1;
    if (extra < 0 || i + size_t(extra) > text.size()) return '?';
    int code = c & (0x3f >> extra);
    for (int k = 0; k < extra; ++k) {
        const unsigned char d = static_cast<unsigned char>(text[i]);
        if ((d & 0xc0) != 0x80) return '?';
        code = code << 6 | (d & 0x3f);
        ++i;
    }
    return code;
}

template <class Fn>
void forEachLine(std::string_view text, Fn&& fn) {
    size_t start = 0;
    for (int line = 0;; ++line) {
        const size_t end = text.find('\n', start);
        fn(text.substr(start, end == std::string_view::npos ? std::string_view::npos : end - start), line);
        if (end == std::string_view::npos) return;
        start = end + 1;
    }
}

}  // namespace

std::filesystem::path labelFontFile() {
    if (const char* file = std::getenv("LUXPLAN_FONT"); file && *file) return file;
    return kDejaVuSans;
}

LabelFont::LabelFont(double pixelHeight) : pixelHeight_(std::max(4.0, pixelHeight)) {
    const LoadedLabelFont& font = loadedLabelFont();
    bitmapScale_ = std::max(1, int(std::lround(pixelHeight_ / kLineAdvance)));
    if (!font.ok) return;
    trueType_ = true;
    int ascent = 0, descent = 0, gap = 0;
    stbtt_GetFontVMetrics(&font.info, &ascent, &descent, &gap);
    scale_ = pixelHeight_ / double(ascent - descent);
    ascent_ = ascent * scale_;
    lineHeight_ = (ascent - descent + gap) * scale_;
}

double LabelFont::lineWidth(std::string_view line) const {
    const stbtt_fontinfo& info = loadedLabelFont().info;
    double x = 0;
    int previous = 0;
    for (size_t i = 0; i < line.size();) {
        const int code = nextCodePoint(line, i);
        if (previous) x += stbtt_GetCodepointKernAdvance(&info, previous, code) * scale_;
        int advance = 0, bearing = 0;
        stbtt_GetCodepointHMetrics(&info, code, &advance, &bearing);
        x += advance * scale_;
        previous = code;
    }
    return x;
}

int LabelFont::width(std::string_view text) const {
    if (!trueType_) return textWidth(text, bitmapScale_);
    double widest = 0;
    forEachLine(text, [&](std::string_view line, int) { widest = std::max(widest, lineWidth(line)); });
    return int(std::ceil(widest));
}

int LabelFont::height(std::string_view text) const {
    if (!trueType_) return textHeight(text, bitmapScale_);
    const int lines = 1 + int(std::count(text.begin(), text.end(), '\n'));
    return int(std::ceil((lines - 1) * lineHeight_ + pixelHeight_));
}

void LabelFont::draw(Image& image, double x, double y, std::string_view text, Rgb color, TextAlign align,
                     double alpha) const {
    if (!trueType_) {
        image.drawText(x, y, text, color, bitmapScale_, align, alpha);
        return;
    }
    const stbtt_fontinfo& info = loadedLabelFont().info;
    std::vector<unsigned char> coverage;
    forEachLine(text, [&](std::string_view line, int index) {
        const double w = lineWidth(line);
        double pen = align == TextAlign::Left ? x : align == TextAlign::Center ? x - w / 2 : x - w;
        pen = std::round(pen);
        const double baseline = std::round(y + index * lineHeight_ + ascent_);
        int previous = 0;
        for (size_t i = 0; i < line.size();) {
            const int code = nextCodePoint(line, i);
            if (previous) pen += stbtt_GetCodepointKernAdvance(&info, previous, code) * scale_;
            const double fx = pen - std::floor(pen);
            int x0 = 0, y0 = 0, x1 = 0, y1 = 0;
            stbtt_GetCodepointBitmapBoxSubpixel(&info, code, float(scale_), float(scale_), float(fx), 0, &x0, &y0, &x1, &y1);
            const int gw = x1 - x0, gh = y1 - y0;
            if (gw > 0 && gh > 0) {
                coverage.assign(size_t(gw) * size_t(gh), 0);
                stbtt_MakeCodepointBitmapSubpixel(&info, coverage.data(), gw, gh, gw, float(scale_), float(scale_),
                                                  float(fx), 0, code);
                const int left = int(std::floor(pen)) + x0, top = int(baseline) + y0;
                for (int row = 0; row < gh; ++row)
                    for (int col = 0; col < gw; ++col)
                        if (const unsigned char a = coverage[size_t(row) * size_t(gw) + size_t(col)])
                            image.blendPixel(left + col, top + row, color, alpha * a / 255.0);
            }
            int advance = 0, bearing = 0;
            stbtt_GetCodepointHMetrics(&info, code, &advance, &bearing);
            pen += advance * scale_;
            previous = code;
        }
    });
}

}  // namespace luxplan
