#include "analysis/statistics.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <optional>
#include <vector>

#include "core/error.h"
#include "core/libm_simd.h"

namespace uvtk::analysis {

namespace {

// The scale on which bins have equal widths.
double binScale(double value, BinSpacing spacing) { return spacing == BinSpacing::Log2 ? std::log2(value) : value; }

}  // namespace

double Histogram::edge(int i) const {
  const int bins = static_cast<int>(weightFraction.size());
  if (i >= bins) return hi;
  const double a = binScale(lo, spacing), b = binScale(hi, spacing);
  double x;
  if (std::isinf(b - a)) {  // values near both ends of the doubles: a blend of the ends
    const double f = static_cast<double>(i) / static_cast<double>(bins);
    x = a * (1.0 - f) + b * f;
  } else {
    x = a + (b - a) * static_cast<double>(i) / static_cast<double>(bins);
  }
  return spacing == BinSpacing::Log2 ? std::exp2(x) : x;
}

namespace {

// ---- Exact sums of weights
//
// A sum of finite weights >= 0 held as a whole number of units, the unit being the last mantissa
// bit of the smallest positive weight, in 32-bit digits kept in 64-bit limbs: adding a weight adds
// its 53-bit mantissa, shifted, into three limbs, and carries wait until a comparison (fewer than
// 2^32 additions cannot overflow a limb). Exact, so a percentile does not depend on the order in
// which its running weight is summed: a rounded running sum that ties the target could go either way.
class SumFormat {
 public:
  // Sums of fewer than 2^32 weights whose biased exponents (1 for subnormals) lie in [lowest, highest].
  SumFormat(int lowest, int highest) : lowest_(lowest), limbs_(std::size_t(highest - lowest + 53 + 32 + 64) / 32) {}

  std::size_t limbs() const { return limbs_; }

  // sum += weight, a weight >= 0 of the format's range.
  void add(std::uint64_t* sum, double weight) const {
    if (!(weight > 0.0)) return;
    const Bits b = bitsOf(weight);
    place(sum, b.mantissa, b.exponent - lowest_);
  }

  // sum = the least whole number of units at or above `value` >= 0: a sum of units reaches the
  // value exactly when it reaches this.
  void setCeiling(std::uint64_t* sum, double value) const {
    std::fill(sum, sum + limbs_, 0);
    if (!(value > 0.0)) return;
    Bits b = bitsOf(value);
    int position = b.exponent - lowest_;
    if (position < 0) {  // below the unit: rounded up
      const int drop = -position;
      const bool fraction = drop >= 64 || (b.mantissa & ((std::uint64_t(1) << drop) - 1)) != 0;
      b.mantissa = (drop >= 64 ? 0 : b.mantissa >> drop) + (fraction ? 1 : 0);
      position = 0;
    }
    UVTK_CHECK(std::size_t(position) / 32 + 3 <= limbs_);
    place(sum, b.mantissa, position);
  }

  // to += from, limb by limb (carries wait).
  void addSum(std::uint64_t* to, const std::uint64_t* from) const {
    for (std::size_t i = 0; i < limbs_; ++i) to[i] += from[i];
  }

  // Carries moved up: every limb but the last holds one digit, so that sums compare limb by limb.
  void normalise(std::uint64_t* sum) const {
    for (std::size_t i = 0; i + 1 < limbs_; ++i) sum[i + 1] += sum[i] >> 32, sum[i] &= 0xffffffffu;
  }

  // Whether a >= b, both normalised.
  bool atLeast(const std::uint64_t* a, const std::uint64_t* b) const {
    for (std::size_t i = limbs_; i-- > 0;)
      if (a[i] != b[i]) return a[i] > b[i];
    return true;
  }

  // The biased exponent (1 for subnormals) of a finite double > 0.
  static int exponentOf(double value) { return bitsOf(value).exponent; }

 private:
  struct Bits {
    std::uint64_t mantissa;  // value = mantissa 2^(exponent - 1075)
    int exponent;
  };
  static Bits bitsOf(double value) {
    std::uint64_t bits;
    std::memcpy(&bits, &value, sizeof bits);
    const int biased = int((bits >> 52) & 0x7ff);
    const std::uint64_t fraction = bits & ((std::uint64_t(1) << 52) - 1);
    return biased == 0 ? Bits{fraction, 1} : Bits{fraction | std::uint64_t(1) << 52, biased};
  }

  void place(std::uint64_t* sum, std::uint64_t mantissa, int position) const {
    const std::size_t limb = std::size_t(position) / 32;
    const int shift = position % 32;
    const std::uint64_t high = mantissa >> (32 - shift);  // the digits above the first: mantissa 2^shift / 2^32
    sum[limb] += (mantissa << shift) & 0xffffffffu;
    sum[limb + 1] += high & 0xffffffffu;
    sum[limb + 2] += high >> 32;
  }

  int lowest_;
  std::size_t limbs_;
};

// ---- The items: values and weights, and which of them enter

struct Items {
  const double* values;
  const double* weights;
  const std::uint8_t* included;  // null: all of them
  std::size_t size;              // of the arrays
  std::size_t count = 0;         // the items that enter

  bool in(std::size_t i) const { return !included || included[i] != 0; }
};

// ---- Weighted percentiles by radix selection

// A double's bits as an unsigned key in the order of the values (negative values' bits flipped,
// the positive ones' sign bit set; -0 counts as +0), so that equal keys are equal values.
std::uint64_t orderKey(double value) {
  if (value == 0.0) value = 0.0;
  std::uint64_t bits;
  std::memcpy(&bits, &value, sizeof bits);
  return bits >> 63 ? ~bits : bits | (std::uint64_t(1) << 63);
}

// One percentile sought: among the items whose keys share the top `bits` bits of `prefix`, after
// the exact weight `below` of the items of smaller keys, the first (in key order) whose running
// weight reaches `target`.
struct Search {
  std::uint64_t prefix = 0;
  int bits = 0;
  std::vector<std::uint64_t> below, target;
  bool found = false;
  double answer = 0.0;

  bool holds(std::uint64_t key) const { return bits == 0 || (key ^ prefix) >> (64 - bits) == 0; }
};

// Keys are refined 11 bits a pass: 2048 buckets, whose counts and sums stay in the caches; 8 bits
// (256 buckets) for fewer than 2^16 items, whose passes cost less than zeroing 2048 buckets' exact
// sums (80 KB a pass, 0.3 ms of a 10 k-face sphere's five statistics).
int digitBitsFor(std::size_t count) { return count < (std::size_t(1) << 16) ? 8 : 11; }
// A bucket of at most this many items is gathered and sorted rather than refined again: sorting
// 2^17 items takes a few milliseconds, a pass over millions of items tens.
constexpr std::size_t kGatherItems = std::size_t(1) << 17;
// Nor is a bucket holding more than a sixteenth of the items (unless it holds only a few hundred):
// one more pass over the items costs less than gathering and selecting most of them, as when the
// first digit splits only the exponents (an angle distortion from 1 - 2^-52 to 100 puts most items
// in one bucket, [1, 2); on a 10 k-face sphere that statistic took 0.7 ms, the others 0.2).
constexpr std::size_t kGatherShare = 16, kGatherAlways = 256;

bool worthGathering(std::size_t bucketItems, std::size_t count) {
  return bucketItems <= kGatherItems && (bucketItems <= kGatherAlways || bucketItems <= count / kGatherShare);
}

// The count and exact weight of each value of the digit below the top `bits` bits of the keys, per
// range of keys sharing those bits (a range numbered by the caller): one pass of the search.
struct DigitTally {
  std::uint64_t prefix = 0;  // a key of the first range
  int bits = 0, digit = 0, shift = 0;
  std::size_t buckets = 0;  // per range: 2^digit
  std::uint64_t mask = 0;
  std::vector<std::size_t> counts;  // per range, `buckets` buckets
  std::vector<std::uint64_t> sums;  // per range and bucket, format.limbs() limbs

  DigitTally(const SumFormat& format, std::uint64_t prefix_, int bits_, std::size_t ranges, int digitBits)
      : prefix(prefix_),
        bits(bits_),
        digit(std::min(digitBits, 64 - bits_)),
        shift(64 - bits_ - digit),
        buckets(std::size_t(1) << digit),
        mask((std::uint64_t(1) << digit) - 1),
        counts(ranges * buckets, 0),
        sums(ranges * buckets * format.limbs(), 0) {}

  // The tally as a pass's loop adds to it: its arrays and digit in locals, as the counts and sums
  // stored are of the types of the tally's own fields, which would be loaded again after each store.
  struct Adder {
    std::size_t* counts;
    std::uint64_t* sums;
    std::size_t buckets, limbs;
    int shift;
    std::uint64_t mask;

    // One item of the range numbered `range`.
    void add(const SumFormat& format, std::size_t range, std::uint64_t key, double weight) const {
      const std::size_t bucket = range * buckets + ((key >> shift) & mask);
      ++counts[bucket];
      format.add(sums + bucket * limbs, weight);
    }
  };
  Adder adder(const SumFormat& format) { return {counts.data(), sums.data(), buckets, format.limbs(), shift, mask}; }
};

// Each pass over the items counts and sums the next digit of the keys in every open search's
// range, and keeps the bucket where the search's running weight reaches its target, until that
// bucket is small enough to sort or the key is whole (one value). O(n) a pass; nothing is copied
// but the last bucket's few items.
// `first`, when given, is the first pass already counted (with another pass over the items) for the
// range every search starts in.
void findPercentiles(const Items& items, const SumFormat& format, std::vector<Search>& searches,
                     DigitTally* first = nullptr) {
  const double *values = items.values, *weights = items.weights;
  const std::size_t count = items.count;
  const std::size_t limbs = format.limbs();
  std::vector<std::uint64_t> running(limbs), after(limbs), start(limbs);
  std::vector<Search*> gather;
  for (;;) {
    // The distinct ranges refined (every open search has as many bits fixed); a whole key is one value.
    std::vector<Search*> open;
    std::vector<std::uint64_t> ranges;  // their prefixes
    for (Search& s : searches)
      if (!s.found) (s.bits == 64 ? gather : open).push_back(&s);
    for (Search* s : open)
      if (std::find(ranges.begin(), ranges.end(), s->prefix) == ranges.end()) ranges.push_back(s->prefix);
    if (ranges.empty()) break;
    const int bits = open.front()->bits;
    const bool counted = first != nullptr;  // every open search is still in the range it started in
    UVTK_CHECK(!counted || (ranges.size() == 1 && ranges[0] == first->prefix && bits == first->bits));
    DigitTally tally = counted ? std::move(*first) : DigitTally(format, ranges[0], bits, ranges.size(), digitBitsFor(count));
    first = nullptr;
    const DigitTally::Adder adder = tally.adder(format);
    const std::uint64_t* const prefixes = ranges.data();
    const std::size_t rangeCount = ranges.size();
    for (std::size_t i = 0; i < items.size && !counted; ++i) {
      if (!items.in(i)) continue;
      const std::uint64_t key = orderKey(values[i]);
      for (std::size_t r = 0; r < rangeCount; ++r)
        if (bits == 0 || (key ^ prefixes[r]) >> (64 - bits) == 0) {
          adder.add(format, r, key, weights[i]);
          break;
        }
    }
    const int digit = tally.digit, shift = tally.shift;
    const std::size_t buckets = tally.buckets;
    const std::uint64_t mask = tally.mask;
    const std::vector<std::size_t>& counts = tally.counts;
    const std::vector<std::uint64_t>& sums = tally.sums;
    // Each range's buckets walked once for all of its searches, in the order of their targets (the
    // searches are made in increasing fractions; searches of one range share the weight below it):
    // for each, the first non-empty bucket at which the running weight reaches its target. One
    // always does, as the range's whole weight reached it when the range was chosen.
    for (std::size_t r = 0; r < ranges.size(); ++r) {
      std::size_t b = 0;
      const Search* previous = nullptr;
      for (Search* s : open) {
        if (s->prefix != ranges[r]) continue;
        if (!previous) running = s->below, start = s->below;
        UVTK_CHECK(!previous || (s->below == start && format.atLeast(s->target.data(), previous->target.data())));
        previous = s;
        for (; b < buckets; ++b) {
          const std::size_t bucket = r * buckets + b;
          if (counts[bucket] == 0) continue;
          after = running;
          format.addSum(after.data(), sums.data() + bucket * limbs);
          format.normalise(after.data());
          if (format.atLeast(after.data(), s->target.data())) break;
          running.swap(after);
        }
        UVTK_CHECK(b < buckets);
        const std::size_t chosen = b;
        s->below = running;
        s->bits = bits + digit;
        s->prefix =
            (s->prefix & ~((mask << shift) | ((std::uint64_t(1) << shift) - 1))) | (std::uint64_t(chosen) << shift);
        if (worthGathering(counts[r * buckets + chosen], count)) s->bits = -s->bits;  // marked: gather it
      }
    }
    // The searches marked are gathered now, the others refined in the next pass.
    for (Search* s : open)
      if (s->bits < 0) s->bits = -s->bits, gather.push_back(s);
    if (!gather.empty()) break;
  }
  if (gather.empty()) return;

  // The last items of each gathered search, sorted by key (equal keys in item order), and walked
  // with the exact running weight.
  struct Item {
    std::uint64_t key;
    double value, weight;
  };
  std::vector<std::vector<Item>> gathered(gather.size());
  for (std::size_t i = 0; i < items.size; ++i) {
    if (!items.in(i)) continue;
    const std::uint64_t key = orderKey(values[i]);
    for (std::size_t g = 0; g < gather.size(); ++g)
      if (gather[g]->holds(key) && (gather[g]->bits < 64 || gathered[g].empty()))
        gathered[g].push_back({key, values[i], weights[i]});
  }
  for (std::size_t g = 0; g < gather.size(); ++g) {
    Search& s = *gather[g];
    std::vector<Item>& list = gathered[g];
    UVTK_CHECK(!list.empty());
    s.found = true;
    if (s.bits == 64) {  // one value: the range's weight reaches the target
      s.answer = list.front().value;
      continue;
    }
    // The least key whose items, with everything below, weigh at least the target: a weighted
    // quickselect (expected linear; sorting the items cost a tenth of a small mesh's judgement).
    // Three-way partitions about the middle item's key; each part's weight summed exactly.
    running = s.below;
    s.answer = list.back().value;
    std::size_t lo = 0, hi = list.size();
    while (lo < hi) {
      const std::uint64_t pivot = list[lo + (hi - lo) / 2].key;
      const auto less = std::partition(list.begin() + std::ptrdiff_t(lo), list.begin() + std::ptrdiff_t(hi),
                                       [pivot](const Item& item) { return item.key < pivot; });
      const auto equal = std::partition(less, list.begin() + std::ptrdiff_t(hi),
                                        [pivot](const Item& item) { return item.key == pivot; });
      after = running;
      for (auto item = list.begin() + std::ptrdiff_t(lo); item != less; ++item) format.add(after.data(), item->weight);
      format.normalise(after.data());
      if (less != list.begin() + std::ptrdiff_t(lo) && format.atLeast(after.data(), s.target.data())) {
        hi = std::size_t(less - list.begin());
        continue;
      }
      for (auto item = less; item != equal; ++item) format.add(after.data(), item->weight);
      format.normalise(after.data());
      if (format.atLeast(after.data(), s.target.data())) {
        s.answer = less->value;
        break;
      }
      running.swap(after);
      lo = std::size_t(equal - list.begin());
    }
  }
  // Searches still open go on from where they are.
  if (std::any_of(searches.begin(), searches.end(), [](const Search& s) { return !s.found; }))
    findPercentiles(items, format, searches);
}

}  // namespace

Statistics weightedStatistics(const double* values, const double* weights, const std::uint8_t* included,
                              std::size_t size, BinSpacing spacing, int bins) {
  UVTK_CHECK(bins >= 1);
  Statistics s;
  s.histogram.spacing = spacing;
  s.histogram.weightFraction.assign(static_cast<std::size_t>(bins), 0.0);
  Items items{values, weights, included, size};
  std::size_t first = 0;
  while (first < size && !items.in(first)) ++first;
  if (first == size) {
    s.histogram.spacing = BinSpacing::Linear;  // no values to space by log2: the edges of [0, 0] would be log2(0)
    return s;
  }

  // One pass for the extremes and the sums in the items' order, and the weights' exponents, in
  // locals (the result's fields may alias the values read: they would be stored every item).
  double lowest = values[first], highest = values[first], totalWeight = 0.0, weightedSum = 0.0;
  std::size_t count = 0;
  int lowestExponent = 2047, highestExponent = 0;
  for (std::size_t i = first; i < size; ++i) {
    if (!items.in(i)) continue;
    ++count;
    const double value = values[i], weight = weights[i];
    UVTK_CHECK(std::isfinite(value) && std::isfinite(weight) && weight >= 0.0);  // the precondition: a NaN derails the search
    if (value < lowest) lowest = value;     // the first of equal smallest values
    if (!(value < highest)) highest = value;  // the last of equal largest ones (std::minmax_element's choice)
    totalWeight += weight, weightedSum += weight * value;
    if (weight > 0.0) {
      const int exponent = SumFormat::exponentOf(weight);
      lowestExponent = std::min(lowestExponent, exponent), highestExponent = std::max(highestExponent, exponent);
    }
  }
  s.min = lowest, s.max = highest, s.totalWeight = totalWeight;
  items.count = count;
  // A log2 histogram needs positive values; where one underflowed to 0 (the measures of a mesh at the
  // edge of the doubles' range) its bins are linear, as its spacing says.
  if (spacing == BinSpacing::Log2 && !(s.min > 0.0)) spacing = s.histogram.spacing = BinSpacing::Linear;
  if (s.totalWeight <= 0.0) return s;
  s.mean = weightedSum / s.totalWeight;

  Histogram& h = s.histogram;
  h.lo = s.min;
  h.hi = s.max;
  // Where the span overflows (values near both ends of the doubles) the bins are placed by halves.
  const double a = binScale(h.lo, spacing), b = binScale(h.hi, spacing);
  const bool halve = std::isinf(b - a);
  const double width = halve ? 0.5 * b - 0.5 * a : b - a, origin = halve ? 0.5 * a : a, scale = halve ? 0.5 : 1.0;
  // The same pass is the percentiles' first: every key shares its top `common` bits with the
  // smallest value's, and the next digit's counts and exact weights are tallied (when the values
  // differ; else the weights are summed exactly as they are).
  UVTK_CHECK(count < (std::size_t(1) << 32));
  const SumFormat format(lowestExponent, highestExponent);
  const std::uint64_t lowestKey = orderKey(s.min), highestKey = orderKey(s.max);
  const int common = lowestKey == highestKey ? 64 : __builtin_clzll(lowestKey ^ highestKey);
  std::optional<DigitTally> firstDigit;
  if (common < 64) firstDigit.emplace(format, lowestKey, common, 1, digitBitsFor(count));
  std::vector<std::uint64_t> whole(format.limbs(), 0);
  // The bins' scale a block at a time: log2 on vectors with glibc's bits (core/libm_simd.h), the
  // items left out taken along (their logarithms unread); linear bins read the values themselves.
  constexpr std::size_t kBlock = 256;
  double logarithms[kBlock];
  double* const binWeights = h.weightFraction.data();
  const std::optional<DigitTally::Adder> digitAdder =
      firstDigit ? std::optional<DigitTally::Adder>(firstDigit->adder(format)) : std::nullopt;
  for (std::size_t block = first; block < size; block += kBlock) {
    const std::size_t n = std::min(kBlock, size - block);
    const double* scaled = values + block;
    if (spacing == BinSpacing::Log2) scaled = logarithms, libm::log2(values + block, logarithms, n);
    for (std::size_t i = block; i < block + n; ++i) {
      if (!items.in(i)) continue;
      const double t = width > 0.0 ? (scale * scaled[i - block] - origin) / width : 0.0;
      const int bin = std::clamp(static_cast<int>(t * bins), 0, bins - 1);
      binWeights[static_cast<std::size_t>(bin)] += weights[i] / totalWeight;
      if (digitAdder)
        digitAdder->add(format, 0, orderKey(values[i]), weights[i]);
      else
        format.add(whole.data(), weights[i]);
    }
  }
  // The whole weight, the buckets' added (fewer than 2^32 items: no limb overflows before the carries).
  for (std::size_t bucket = 0; firstDigit && bucket < firstDigit->buckets; ++bucket)
    format.addSum(whole.data(), firstDigit->sums.data() + bucket * format.limbs());
  format.normalise(whole.data());

  // The percentiles, their targets a fraction of the total as summed in order above.
  const double fractions[4] = {0.10, 0.50, 0.90, 0.99};
  double* const percentiles[4] = {&s.p10, &s.p50, &s.p90, &s.p99};
  std::vector<Search> searches(4);
  for (int k = 0; k < 4; ++k) {
    Search& search = searches[std::size_t(k)];
    search.target.assign(format.limbs(), 0);
    format.setCeiling(search.target.data(), fractions[k] * s.totalWeight);
    search.below.assign(format.limbs(), 0);
    search.prefix = lowestKey;
    search.bits = common;
    // Rounding may leave the whole weight short of the target: then the largest value.
    if (!format.atLeast(whole.data(), search.target.data())) search.found = true, search.answer = s.max;
  }
  findPercentiles(items, format, searches, firstDigit ? &*firstDigit : nullptr);
  for (int k = 0; k < 4; ++k) *percentiles[k] = searches[std::size_t(k)].answer;
  return s;
}

Statistics weightedStatistics(const std::vector<double>& values, const std::vector<double>& weights,
                              BinSpacing spacing, int bins) {
  UVTK_CHECK(values.size() == weights.size());
  return weightedStatistics(values.data(), weights.data(), nullptr, values.size(), spacing, bins);
}

}  // namespace uvtk::analysis
