#include "render/procedural.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <functional>
#include <string>
#include <vector>

#include "core/error.h"
#include "render/font.h"

namespace uvtk::render {

namespace {

constexpr int kCheckerMax = 16384;
constexpr int kCheckerDefaultSquare = 8;
constexpr int kGridMin = 64, kGridMax = 8192, kGridDefault = 1024;
constexpr int kCells = 8;  // cells per side of the uv grid
constexpr int kSphereMapMin = 8, kSphereMapMax = 8192, kSphereMapDefault = 256;
constexpr int kSphereMapMaxChecks = 64, kSphereMapDefaultChecks = 8;
constexpr int kCubeDefault = 64, kCubeMax = 4096, kCubeIndexMax = 256;

// The nearest 8-bit value, as a float: round(v 255) / 255.
float eightBit(double v) { return float(std::round(v * 255.0) / 255.0); }

// HSV to RGB with value 1 (Smith, "Color gamut transform pairs", SIGGRAPH 1978): hue in turns.
std::array<double, 3> hsvToRgb(double hue, double saturation) {
  const double h = hue * 6.0;
  const int sector = int(std::floor(h)) % 6;
  const double f = h - std::floor(h);
  const double p = 1.0 - saturation, q = 1.0 - saturation * f, t = 1.0 - saturation * (1.0 - f);
  switch (sector) {
    case 0:
      return {1.0, t, p};
    case 1:
      return {q, 1.0, p};
    case 2:
      return {p, 1.0, t};
    case 3:
      return {p, q, 1.0};
    case 4:
      return {t, p, 1.0};
    default:
      return {1.0, p, q};
  }
}

// The background of the cell in column `column` (A = 0, along u) and row `row` (1 = 0, along v):
// the hue turns with the column, the saturation grows with the row from 0.15 to 0.50, the value
// is 1, so every channel stays at or above 1/2 and black reads on all 64 colours.
std::array<float, 3> cellColour(int column, int row) {
  const std::array<double, 3> rgb = hsvToRgb(double(column) / kCells, 0.15 + 0.05 * row);
  return {eightBit(rgb[0]), eightBit(rgb[1]), eightBit(rgb[2])};
}

void setPixel(Image& image, int x, int y, const std::array<float, 3>& rgb) {
  for (int c = 0; c < 3; ++c) image.at(x, y, c) = rgb[std::size_t(c)];
}

// The digits of a decimal count (no sign, no spaces, at most 9 digits), or -1.
int parseCount(const std::string& text) {
  if (text.empty() || text.size() > 9 ||
      !std::all_of(text.begin(), text.end(), [](char c) { return c >= '0' && c <= '9'; }))
    return -1;
  return std::stoi(text);
}

// The fields of `text` between its colons.
std::vector<std::string> splitColons(const std::string& text) {
  std::vector<std::string> fields;
  std::size_t begin = 0;
  for (std::size_t colon; (colon = text.find(':', begin)) != std::string::npos; begin = colon + 1)
    fields.push_back(text.substr(begin, colon - begin));
  fields.push_back(text.substr(begin));
  return fields;
}

}  // namespace

Texture checkerTexture(int n, int c) {
  if (!(1 <= n && n <= kCheckerMax && 1 <= c && c <= kCheckerMax))
    throw UsageError("checker texture: expected 1 <= N, C <= 16384, got N = " + std::to_string(n) +
                     ", C = " + std::to_string(c));
  checkTextureSize(n, n);  // before allocating: from N = 11586 on, N x N float RGBA exceeds 2 GiB
  TexelLevel base;
  base.width = base.height = n;
  base.texels.resize(std::size_t(n) * std::size_t(n));
  const Rgba white(1.0f, 1.0f, 1.0f, 1.0f), black(0.0f, 0.0f, 0.0f, 1.0f);
  for (int j = 0; j < n; ++j)
    for (int i = 0; i < n; ++i) base.at(i, j) = (i / c + j / c) % 2 == 0 ? white : black;
  return Texture(std::move(base), true);
}

// The layout, in pixels of the N x N image (row 0 at the top, v = 1): cell boundaries at
// b_k = k N / 8 (integer division), k = 0..8; cell column A..H spans x in [b_k, b_k+1) left to
// right, cell row 8..1 spans y in [b_k, b_k+1) top to bottom. Black lines on every inner boundary
// (x = b_k or y = b_k, k = 1..7) and on the two outermost pixels of each side. Each cell's label
// (e.g. "C5"), scale max(1, floor(h / 21)) for the cell height h = N / 8 (about a third of it),
// is centred in the cell when it fits between the cell's lines (in every cell from N = 104 on).
// The arrow of cell A1 (width w, height h, top y0) lies below the label: a shaft along row
// y0 + 5h/6 (scale rows thick) from x = w/5 to x = 4w/5, ending in a head whose column
// 4w/5 - d spans rows y0 + 5h/6 +- d/2 for d = 0..h/6.
Image uvGridImage(int n) {
  if (!(kGridMin <= n && n <= kGridMax))
    throw UsageError("uvgrid texture: expected 64 <= N <= 8192, got N = " + std::to_string(n));
  Image image(n, n, 3);
  std::array<int, kCells + 1> bound{};
  for (int k = 0; k <= kCells; ++k) bound[std::size_t(k)] = k * n / kCells;
  const int scale = std::max(1, (n / kCells) / 21);
  const std::array<float, 3> black{0.0f, 0.0f, 0.0f};
  const float ink[4] = {0.0f, 0.0f, 0.0f, 1.0f};

  for (int cellY = 0; cellY < kCells; ++cellY)
    for (int column = 0; column < kCells; ++column) {
      const int row = kCells - 1 - cellY;  // 0 for digit 1, at the bottom (v = 0)
      const int x0 = bound[std::size_t(column)], y0 = bound[std::size_t(cellY)];
      const int w = bound[std::size_t(column) + 1] - x0, h = bound[std::size_t(cellY) + 1] - y0;
      const std::array<float, 3> background = cellColour(column, row);
      for (int y = y0; y < y0 + h; ++y)
        for (int x = x0; x < x0 + w; ++x) setPixel(image, x, y, background);

      const std::string label{char('A' + column), char('1' + row)};
      const int labelWidth = textWidth(label, scale), labelHeight = textHeight(scale);
      if (labelWidth <= w - 2 && labelHeight <= h - 2)
        drawText(image, x0 + (w - labelWidth) / 2, y0 + (h - labelHeight) / 2, label, scale, ink);
    }

  for (int p = 0; p < n; ++p) {
    for (int k = 1; k < kCells; ++k) {
      setPixel(image, bound[std::size_t(k)], p, black);
      setPixel(image, p, bound[std::size_t(k)], black);
    }
    for (int edge : {0, 1, n - 2, n - 1}) {
      setPixel(image, edge, p, black);
      setPixel(image, p, edge, black);
    }
  }

  // The arrow in cell A1 (column 0, the bottom cell row), pointing to +u.
  const int w = bound[1], y0 = bound[kCells - 1], h = n - y0;
  const int axis = y0 + 5 * h / 6, tail = w / 5, tip = 4 * w / 5;
  for (int x = tail; x <= tip; ++x)
    for (int y = axis - scale / 2; y < axis - scale / 2 + scale; ++y) setPixel(image, x, y, black);
  for (int d = 0; d <= h / 6; ++d)
    for (int y = axis - d / 2; y <= axis + d / 2; ++y) setPixel(image, tip - d, y, black);
  return image;
}

namespace {

// A procedural texture's name parsed: checker:N[:C] or uvgrid[:N].
enum class ProceduralKind { Checker, Uvgrid, SphereMap, Cube, CubeIndex };

struct ProceduralName {
  ProceduralKind kind = ProceduralKind::Checker;
  int n = 0, c = 0;
};

// A name is procedural when it is the bare word or the word and a colon: "checker.png" is a file.
bool names(const std::string& name, const std::string& word) {
  return name == word || name.compare(0, word.size() + 1, word + ":") == 0;
}

// The counts after the word: `fields` holds the name split at its colons, the counts missing from
// it take their defaults; -1 marks a malformed count or too many fields.
std::vector<int> counts(const std::vector<std::string>& fields, const std::vector<int>& defaults) {
  std::vector<int> out = defaults;
  if (fields.size() > defaults.size() + 1) return std::vector<int>(defaults.size(), -1);
  for (std::size_t k = 1; k < fields.size(); ++k) out[k - 1] = parseCount(fields[k]);
  return out;
}

bool within(int value, int lo, int hi) { return lo <= value && value <= hi; }

std::optional<ProceduralName> parseProceduralName(const std::string& name) {
  const std::vector<std::string> fields = splitColons(name);
  const auto malformed = [&](const std::string& expected) {
    return UsageError("texture '" + name + "': expected " + expected);
  };
  if (names(name, "checker")) {
    const std::vector<int> nc = counts(fields, {-1, kCheckerDefaultSquare});
    if (!within(nc[0], 1, kCheckerMax) || !within(nc[1], 1, kCheckerMax))
      throw malformed("checker:N[:C] with 1 <= N, C <= 16384");
    return ProceduralName{ProceduralKind::Checker, nc[0], nc[1]};
  }
  if (names(name, "uvgrid")) {
    const std::vector<int> n = counts(fields, {kGridDefault});
    if (!within(n[0], kGridMin, kGridMax)) throw malformed("uvgrid[:N] with 64 <= N <= 8192");
    return ProceduralName{ProceduralKind::Uvgrid, n[0], 0};
  }
  if (names(name, "spheremap")) {
    const std::vector<int> nk = counts(fields, {kSphereMapDefault, kSphereMapDefaultChecks});
    if (!within(nk[0], kSphereMapMin, kSphereMapMax) || !within(nk[1], 1, kSphereMapMaxChecks))
      throw malformed("spheremap[:N[:K]] with 8 <= N <= 8192, 1 <= K <= 64");
    return ProceduralName{ProceduralKind::SphereMap, nk[0], nk[1]};
  }
  if (names(name, "cube")) {
    const std::vector<int> n = counts(fields, {kCubeDefault});
    if (!within(n[0], 1, kCubeMax)) throw malformed("cube[:N] with 1 <= N <= 4096");
    return ProceduralName{ProceduralKind::Cube, n[0], 0};
  }
  if (names(name, "cubeindex")) {
    const std::vector<int> n = counts(fields, {kCubeDefault});
    if (!within(n[0], 1, kCubeIndexMax)) throw malformed("cubeindex[:N] with 1 <= N <= 256");
    return ProceduralName{ProceduralKind::CubeIndex, n[0], 0};
  }
  return std::nullopt;
}

// Six N x N faces whose texel (i, j) of face f is colour(f, i, j) (8-bit values).
CubeTexture cubeFromTexels(int n, const std::function<std::array<int, 3>(int, int, int)>& colour) {
  std::vector<Texture> faces;
  for (int f = 0; f < kCubeFaceCount; ++f) {
    TexelLevel level{n, n, {}};
    level.texels.reserve(std::size_t(n) * std::size_t(n));
    for (int j = 0; j < n; ++j)
      for (int i = 0; i < n; ++i) {
        const std::array<int, 3> c = colour(f, i, j);
        level.texels.push_back(Rgba(float(c[0]), float(c[1]), float(c[2]), 255.0f) / 255.0f);
      }
    faces.emplace_back(std::move(level), true);
  }
  return CubeTexture(std::move(faces));
}

}  // namespace

CubeTexture cubeCheckerTexture(int n) {
  if (!within(n, 1, kCubeMax)) throw UsageError("cube texture: expected 1 <= N <= 4096, got " + std::to_string(n));
  static constexpr int kFaceColour[kCubeFaceCount][3] = {{255, 0, 0},   {0, 255, 255}, {0, 255, 0},
                                                         {255, 0, 255}, {0, 0, 255},   {255, 255, 0}};
  const int c = std::max(1, n / 8);
  return cubeFromTexels(n, [c](int f, int i, int j) {
    const int divisor = (i / c + j / c) % 2 == 0 ? 1 : 2;
    return std::array<int, 3>{kFaceColour[f][0] / divisor, kFaceColour[f][1] / divisor, kFaceColour[f][2] / divisor};
  });
}

CubeTexture cubeIndexTexture(int n) {
  if (!within(n, 1, kCubeIndexMax))
    throw UsageError("cubeindex texture: expected 1 <= N <= 256, got " + std::to_string(n));
  return cubeFromTexels(n, [](int f, int i, int j) { return std::array<int, 3>{i, j, 40 * (f + 1)}; });
}

Texture sphereMapCheckerTexture(int n, int k) {
  if (!within(n, kSphereMapMin, kSphereMapMax) || !within(k, 1, kSphereMapMaxChecks))
    throw UsageError("spheremap texture: expected 8 <= N <= 8192 and 1 <= K <= 64, got N = " + std::to_string(n) +
                     ", K = " + std::to_string(k));
  TexelLevel level{n, n, {}};
  level.texels.reserve(std::size_t(n) * std::size_t(n));
  const Rgba grey = Rgba(128, 128, 128, 255) / 255.0f;
  const std::array<Rgba, 4> checks = {Rgba(255, 255, 255, 255) / 255.0f, Rgba(0, 0, 0, 255) / 255.0f,
                                      Rgba(255, 160, 0, 255) / 255.0f, Rgba(0, 64, 160, 255) / 255.0f};
  for (int j = 0; j < n; ++j)
    for (int i = 0; i < n; ++i) {
      const double x = 2.0 * (i + 0.5) / n - 1.0, y = 2.0 * (j + 0.5) / n - 1.0;
      const double d2 = x * x + y * y;
      if (d2 > 1.0) {
        level.texels.push_back(grey);
        continue;
      }
      // SPHERE_MAP inverted (§6): m = 4 sqrt(1 - d^2) for a unit r, so r_z = 1 - 2 d^2, theta = 2 asin(d).
      const double theta = 2.0 * std::asin(std::sqrt(d2));
      double phi = std::atan2(y, x);
      if (phi < 0.0) phi += kTwoPi;
      const int a = std::min(k - 1, int(std::floor(theta * k / kPi)));
      const int b = std::min(2 * k - 1, int(std::floor(phi * k / kPi)));
      const bool behind = !(d2 < 0.5);
      level.texels.push_back(checks[std::size_t(2 * behind + (a + b) % 2)]);
    }
  return Texture(std::move(level), true);
}

bool isProceduralName(const std::string& name) { return parseProceduralName(name).has_value(); }

bool isProceduralCubeName(const std::string& name) {
  const std::optional<ProceduralName> parsed = parseProceduralName(name);
  return parsed && (parsed->kind == ProceduralKind::Cube || parsed->kind == ProceduralKind::CubeIndex);
}

std::optional<Texture> proceduralTexture(const std::string& name) {
  const std::optional<ProceduralName> parsed = parseProceduralName(name);
  if (!parsed) return std::nullopt;
  switch (parsed->kind) {
    case ProceduralKind::Checker:
      return checkerTexture(parsed->n, parsed->c);
    case ProceduralKind::Uvgrid:
      return Texture::fromImage(uvGridImage(parsed->n), true);
    case ProceduralKind::SphereMap:
      return sphereMapCheckerTexture(parsed->n, parsed->c);
    case ProceduralKind::Cube:
    case ProceduralKind::CubeIndex:
      break;
  }
  return std::nullopt;
}

std::optional<CubeTexture> proceduralCubeTexture(const std::string& name) {
  const std::optional<ProceduralName> parsed = parseProceduralName(name);
  if (!parsed) return std::nullopt;
  if (parsed->kind == ProceduralKind::Cube) return cubeCheckerTexture(parsed->n);
  if (parsed->kind == ProceduralKind::CubeIndex) return cubeIndexTexture(parsed->n);
  return std::nullopt;
}

}  // namespace uvtk::render
