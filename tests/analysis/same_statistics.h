// Two Statistics equal field by field, bit for bit: the analysis tests' check that a second way of
// computing them (other threads, masked items) changes nothing.
#pragma once

#include <gtest/gtest.h>

#include "analysis/statistics.h"

namespace uvtk::analysis {

inline void expectSameStatistics(const Statistics& a, const Statistics& b) {
  EXPECT_EQ(a.totalWeight, b.totalWeight);
  EXPECT_EQ(a.mean, b.mean);
  EXPECT_EQ(a.p10, b.p10);
  EXPECT_EQ(a.p50, b.p50);
  EXPECT_EQ(a.p90, b.p90);
  EXPECT_EQ(a.p99, b.p99);
  EXPECT_EQ(a.min, b.min);
  EXPECT_EQ(a.max, b.max);
  EXPECT_EQ(a.histogram.spacing, b.histogram.spacing);
  EXPECT_EQ(a.histogram.lo, b.histogram.lo);
  EXPECT_EQ(a.histogram.hi, b.histogram.hi);
  EXPECT_EQ(a.histogram.weightFraction, b.histogram.weightFraction);
}

}  // namespace uvtk::analysis
