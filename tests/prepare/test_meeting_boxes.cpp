// The grid search for boxes that meet (acd/algo/meeting_boxes.hpp), against every pair tested.
#include <acd/algo/meeting_boxes.hpp>

#include <gtest/gtest.h>

#include <random>
#include <set>
#include <utility>
#include <vector>

namespace {

using acd::FloatBox;
using Pairs = std::multiset<std::pair<int, int>>;

/// Every pair that meets, from all pairs: the oracle.
Pairs meetingPairs(const std::vector<FloatBox>& boxes) {
  Pairs out;
  for (std::size_t i = 0; i < boxes.size(); ++i)
    for (std::size_t j = i + 1; j < boxes.size(); ++j) {
      bool meet = true;
      for (int k = 0; k < 3; ++k) meet = meet && boxes[i].lo[k] <= boxes[j].hi[k] && boxes[j].lo[k] <= boxes[i].hi[k];
      if (meet) out.insert({static_cast<int>(i), static_cast<int>(j)});
    }
  return out;
}

/// What the grid visits, every visit kept (a pair visited twice would show twice).
Pairs visited(const std::vector<FloatBox>& boxes, bool& gridded) {
  Pairs out;
  gridded = acd::forEachMeetingPair(boxes, [&](int i, int j) {
    EXPECT_LT(i, j);
    out.insert({i, j});
  });
  return out;
}

FloatBox boxAround(float x, float y, float z, float half) { return {{x - half, y - half, z - half}, {x + half, y + half, z + half}}; }

// Small boxes about one size spread over a surface (a sphere), like a mesh's faces.
TEST(MeetingBoxes, FindsEveryMeetingPairOnceAmongBoxesOfASurface) {
  std::mt19937 rng(3);
  std::normal_distribution<float> gauss;
  std::uniform_real_distribution<float> size(0.01f, 0.04f);
  std::vector<FloatBox> boxes;
  for (int b = 0; b < 3000; ++b) {
    float x = gauss(rng), y = gauss(rng), z = gauss(rng);
    const float r = std::sqrt(x * x + y * y + z * z);
    boxes.push_back(boxAround(x / r, y / r, z / r, size(rng)));
  }
  bool gridded = false;
  const Pairs found = visited(boxes, gridded);
  EXPECT_TRUE(gridded);
  EXPECT_EQ(found, meetingPairs(boxes));
  EXPECT_GT(found.size(), 3000u);
}

// Boxes that only touch, on cell walls or not, meet; identical boxes, flat boxes (a face in a
// coordinate plane) and boxes of one point are found too.
TEST(MeetingBoxes, TouchingFlatAndRepeatedBoxesAreFound) {
  std::vector<FloatBox> boxes;
  for (int i = 0; i < 20; ++i)
    for (int j = 0; j < 20; ++j) boxes.push_back({{float(i), float(j), 0.f}, {float(i + 1), float(j + 1), 0.f}});  // a flat tiling
  boxes.push_back(boxes[57]);
  boxes.push_back({{3.f, 4.f, 0.f}, {3.f, 4.f, 0.f}});  // a point on four tiles' corner
  boxes.push_back({{2.5f, 2.5f, -1.f}, {2.5f, 2.5f, 1.f}});  // a stick through one tile
  bool gridded = false;
  const Pairs found = visited(boxes, gridded);
  EXPECT_TRUE(gridded);
  EXPECT_EQ(found, meetingPairs(boxes));
}

// A few boxes across everything among many small ones: found as well, through the grid while
// their listings stay within bounds, else the search declines and visits nothing.
TEST(MeetingBoxes, LargeBoxesAmongSmallOnesAreFoundOrTheSearchDeclines) {
  std::mt19937 rng(5);
  std::uniform_real_distribution<float> at(0.f, 10.f);
  std::vector<FloatBox> boxes;
  for (int b = 0; b < 2000; ++b) boxes.push_back(boxAround(at(rng), at(rng), at(rng), 0.05f));
  boxes.push_back({{0.f, 0.f, 4.f}, {10.f, 10.f, 4.2f}});  // a slab across the whole box
  bool gridded = false;
  Pairs found = visited(boxes, gridded);
  EXPECT_TRUE(gridded);
  EXPECT_EQ(found, meetingPairs(boxes));
  for (int b = 0; b < 40; ++b) boxes.push_back({{0.f, 0.f, 0.f}, {10.f, 10.f, 10.f}});  // each in every cell
  found = visited(boxes, gridded);
  EXPECT_FALSE(gridded);
  EXPECT_TRUE(found.empty());
}

TEST(MeetingBoxes, NoneOrOneBoxGivesNoPair) {
  bool gridded = false;
  EXPECT_TRUE(visited({}, gridded).empty());
  EXPECT_TRUE(visited({boxAround(0, 0, 0, 1)}, gridded).empty());
}

}  // namespace
