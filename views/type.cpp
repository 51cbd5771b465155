#include "views/type.h"

#include <ft2build.h>
#include FT_FREETYPE_H

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <limits>
#include <map>
#include <mutex>
#include <string>
#include <tuple>
#include <vector>

#include "core/error.h"
#include "core/plugin.h"

namespace uvtk::views {

namespace {

// A glyph at one size, rasterised once: its coverage (0..255, `width` x `rows`, row 0 at the top)
// placed `left` pixels right of the pen and `top` pixels above the baseline.
struct Glyph {
  FT_UInt index = 0;
  int left = 0, top = 0, width = 0, rows = 0;
  int advance = 0;  // whole pixels: pens stay on the pixel grid, so equal text draws equal pixels
  std::vector<std::uint8_t> coverage;
};

struct PlacedGlyph {
  const Glyph* glyph;
  long long x;  // the glyph's pen position, relative to the box's left edge
};

struct Line {
  std::vector<PlacedGlyph> glyphs;
  TextMetrics metrics;
};

// FreeType, opened when the views first draw text rather than linked: loading it (and libpng and
// Brotli, which it needs) took every uvtk process 0.15 to 0.25 ms at start, and most draw no text
// (docs/benchmarks.md). Its soname has been libfreetype.so.6 since FreeType 2.0.
struct FreeType {
  decltype(&FT_Init_FreeType) initFreeType;
  decltype(&FT_Done_FreeType) doneFreeType;
  decltype(&FT_New_Face) newFace;
  decltype(&FT_Set_Char_Size) setCharSize;
  decltype(&FT_Get_Char_Index) getCharIndex;
  decltype(&FT_Load_Glyph) loadGlyph;
  decltype(&FT_Get_Kerning) getKerning;
};

const FreeType& freeType() {
  static const FreeType loaded = [] {
    constexpr const char* kLibrary = "libfreetype.so.6";
    OpenedLibrary library(kLibrary);
    FreeType f{};
    library.bind(f.initFreeType, "FT_Init_FreeType");
    library.bind(f.doneFreeType, "FT_Done_FreeType");
    library.bind(f.newFace, "FT_New_Face");
    library.bind(f.setCharSize, "FT_Set_Char_Size");
    library.bind(f.getCharIndex, "FT_Get_Char_Index");
    library.bind(f.loadGlyph, "FT_Load_Glyph");
    library.bind(f.getKerning, "FT_Get_Kerning");
    if (!library.error().empty())
      throw InputError(std::string(kLibrary) + ": error: cannot load FreeType for the views' text (" +
                       library.error() + "); install libfreetype6");
    return f;
  }();
  return loaded;
}

// FreeType's library and faces are not thread-safe: every use of them, and of the cache they
// fill, holds `mutex`. Glyphs are never evicted and std::map never moves its nodes, so a Glyph
// found under the lock may be read after it is released.
class Typeface {
 public:
  Typeface() {
    if (FT_Error error = ft_.initFreeType(&library_))
      throw InputError("FreeType: error: cannot initialise (FreeType error " + std::to_string(error) + ")");
  }
  ~Typeface() { ft_.doneFreeType(library_); }  // also frees the faces
  Typeface(const Typeface&) = delete;
  Typeface& operator=(const Typeface&) = delete;

  Line layOut(const std::u32string& text, double pixelSize, Weight weight) {
    UVTK_CHECK(std::isfinite(pixelSize) && pixelSize >= 1.0 && pixelSize <= 512.0);
    const FT_F26Dot6 size = FT_F26Dot6(std::lround(pixelSize * 64.0));
    const std::lock_guard<std::mutex> lock(mutex_);
    FT_Face face = faceAt(weight, size);
    // The face's line box; hinted TrueType sizes round the ascender up and the descender down.
    Line line;
    TextMetrics& m = line.metrics;
    m.ascent = int((face->size->metrics.ascender + 63) / 64);
    m.descent = int((-face->size->metrics.descender + 63) / 64);
    long long pen = 0, inkLeft = 0, inkRight = 0;
    FT_UInt previous = 0;
    for (char32_t c : text) {
      const Glyph& glyph = glyphOf(face, c, size, weight);
      if (previous != 0 && glyph.index != 0 && FT_HAS_KERNING(face)) {
        // Unfitted and rounded here: FT_KERNING_DEFAULT scales pairs down below 25 pixels per
        // em, to nothing for most pairs at the views' sizes (A V: -0.83 pixels at 13 gives 0).
        FT_Vector kerning{0, 0};
        if (ft_.getKerning(face, previous, glyph.index, FT_KERNING_UNFITTED, &kerning) == 0)
          pen += std::lround(kerning.x / 64.0);
      }
      line.glyphs.push_back({&glyph, pen});
      if (glyph.width > 0 && glyph.rows > 0) {
        inkLeft = std::min(inkLeft, pen + glyph.left);
        inkRight = std::max(inkRight, pen + glyph.left + glyph.width);
        m.ascent = std::max(m.ascent, glyph.top);
        m.descent = std::max(m.descent, glyph.rows - glyph.top);
      }
      pen += glyph.advance;
      previous = glyph.index;
    }
    // Ink left of the pen's start (a negative left bearing) moves the whole line right.
    for (PlacedGlyph& placed : line.glyphs) placed.x -= inkLeft;
    const long long width = std::max(pen, inkRight) - inkLeft;
    UVTK_CHECK(width <= std::numeric_limits<int>::max());
    m.width = int(width);
    m.height = m.ascent + m.descent;
    return line;
  }

 private:
  FT_Face faceAt(Weight weight, FT_F26Dot6 size) {
    const int w = weight == Weight::Bold ? 1 : 0;
    if (!faces_[w]) {
      const char* path = w == 1 ? UVTK_FONT_BOLD : UVTK_FONT_REGULAR;
      if (FT_Error error = ft_.newFace(library_, path, 0, &faces_[w]))
        throw InputError(std::string(path) + ": error: cannot load the typeface of the views' text (FreeType error " +
                         std::to_string(error) + "); install fonts-dejavu-core");
    }
    if (sizes_[w] != size) {
      if (FT_Error error = ft_.setCharSize(faces_[w], 0, size, 72, 72))  // at 72 dpi a point is a pixel
        throw InputError(std::string(faces_[w]->family_name) + ": error: cannot scale to " +
                         std::to_string(size / 64.0) + " pixels (FreeType error " + std::to_string(error) + ")");
      sizes_[w] = size;
    }
    return faces_[w];
  }

  const Glyph& glyphOf(FT_Face face, char32_t c, FT_F26Dot6 size, Weight weight) {
    const auto key = std::make_tuple(c, size, weight);
    if (auto found = glyphs_.find(key); found != glyphs_.end()) return found->second;
    Glyph glyph;
    glyph.index = ft_.getCharIndex(face, FT_ULong(c));
    if (FT_Error error = ft_.loadGlyph(face, glyph.index, FT_LOAD_RENDER | FT_LOAD_TARGET_NORMAL)) {
      char name[16];
      std::snprintf(name, sizeof name, "U+%04X", unsigned(c));
      throw InputError(std::string(face->family_name) + ": error: cannot draw " + name + " (FreeType error " +
                       std::to_string(error) + ")");
    }
    const FT_GlyphSlot slot = face->glyph;
    const FT_Bitmap& bitmap = slot->bitmap;
    UVTK_CHECK(bitmap.pixel_mode == FT_PIXEL_MODE_GRAY && bitmap.num_grays == 256 && bitmap.pitch >= 0);
    glyph.left = slot->bitmap_left;
    glyph.top = slot->bitmap_top;
    glyph.width = int(bitmap.width);
    glyph.rows = int(bitmap.rows);
    glyph.advance = int((slot->advance.x + 32) / 64);
    glyph.coverage.resize(std::size_t(glyph.width) * std::size_t(glyph.rows));
    for (int row = 0; row < glyph.rows; ++row)
      std::copy_n(bitmap.buffer + std::ptrdiff_t(row) * bitmap.pitch, glyph.width,
                  glyph.coverage.begin() + std::ptrdiff_t(row) * glyph.width);
    return glyphs_.emplace(key, std::move(glyph)).first->second;
  }

  const FreeType& ft_ = freeType();
  std::mutex mutex_;
  FT_Library library_ = nullptr;
  FT_Face faces_[2] = {nullptr, nullptr};  // Regular, Bold; loaded on first use
  FT_F26Dot6 sizes_[2] = {0, 0};           // each face's current size
  std::map<std::tuple<char32_t, FT_F26Dot6, Weight>, Glyph> glyphs_;
};

Typeface& typeface() {
  static Typeface instance;  // C++11 statics: initialised once, by the first thread to get here
  return instance;
}

// UTF-8 to code points; a malformed sequence (overlong, a surrogate, beyond U+10FFFF, cut
// short, a stray continuation byte) becomes one U+FFFD and decoding resumes at the next byte.
std::u32string decode(const std::string& utf8) {
  std::u32string out;
  const auto byte = [&](std::size_t i) { return static_cast<unsigned char>(utf8[i]); };
  for (std::size_t i = 0; i < utf8.size();) {
    const unsigned char lead = byte(i);
    const int length = lead < 0x80 ? 1 : (lead >> 5) == 0x6 ? 2 : (lead >> 4) == 0xE ? 3 : (lead >> 3) == 0x1E ? 4 : 0;
    char32_t c = length == 1 ? lead : length == 2 ? lead & 0x1F : length == 3 ? lead & 0x0F : lead & 0x07;
    bool valid = length > 0 && i + std::size_t(length) <= utf8.size();
    for (int k = 1; valid && k < length; ++k) {
      valid = (byte(i + std::size_t(k)) & 0xC0) == 0x80;
      c = (c << 6) | (byte(i + std::size_t(k)) & 0x3F);
    }
    constexpr char32_t kLeast[] = {0, 0, 0x80, 0x800, 0x10000};  // below these: overlong
    valid = valid && c >= kLeast[length] && c <= 0x10FFFF && !(c >= 0xD800 && c <= 0xDFFF);
    out.push_back(valid ? c : U'\uFFFD');
    i += valid ? std::size_t(length) : 1;
  }
  return out;
}

}  // namespace

TextMetrics measureText(const std::string& utf8, double pixelSize, Weight weight) {
  return typeface().layOut(decode(utf8), pixelSize, weight).metrics;
}

void drawText(Image& image, int x, int top, const std::string& utf8, double pixelSize, const Vec3& colour, Weight weight) {
  UVTK_CHECK(image.channels == 3 && colour.allFinite());
  const Line line = typeface().layOut(decode(utf8), pixelSize, weight);
  const long long baseline = (long long)top + line.metrics.ascent;
  for (const PlacedGlyph& placed : line.glyphs) {
    const Glyph& g = *placed.glyph;
    const long long left = x + placed.x + g.left, first = baseline - g.top;
    for (int row = 0; row < g.rows; ++row) {
      const long long j = first + row;
      if (j < 0 || j >= image.height) continue;
      for (int col = 0; col < g.width; ++col) {
        const long long i = left + col;
        const std::uint8_t c = g.coverage[std::size_t(row) * std::size_t(g.width) + std::size_t(col)];
        if (i < 0 || i >= image.width || c == 0) continue;
        const float a = c / 255.0f;
        for (int k = 0; k < 3; ++k) {
          float& value = image.at(int(i), int(j), k);
          value = float(colour[k]) * a + value * (1.0f - a);  // exactly `colour` where fully covered
        }
      }
    }
  }
}

}  // namespace uvtk::views
