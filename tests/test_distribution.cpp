// The population shared out over ranks (harness/distribution.hpp, docs/mpi.md): own_members gives
// rank r of R the whole blocks of kSumBlock members from ⌊B r / R⌋ to ⌊B (r + 1) / R⌋ (B blocks,
// the last one short when kSumBlock does not divide N), clipped to N. Checked against that closed
// form and against what it promises: the ranges tile [0, N) in rank order, begin on block
// boundaries, and hold numbers of blocks that differ by at most one.
#include <boost/test/unit_test.hpp>

#include <algorithm>
#include <vector>

#include "harness/compensated_sum.hpp"
#include "harness/distribution.hpp"

namespace unit_distribution {

using namespace dlpverify;

namespace {

// ⌊B r / R⌋, the first block of rank r of R (the header's rule, in exact integers): rank r holds
// ⌊B (r + 1) / R⌋ − ⌊B r / R⌋ blocks, ⌊B / R⌋ or one more.
long long first_block(long long blocks, long long rank, long long ranks) { return blocks * rank / ranks; }

}  // namespace

BOOST_AUTO_TEST_SUITE(distribution)

// N from one member to several blocks and a few more (block counts 1 … 9, N a multiple of the
// block or not), on 1 … 8 ranks — 7 blocks on 3 ranks, 5 on 2, more ranks than blocks.
BOOST_AUTO_TEST_CASE(ranks_tile_the_population_by_whole_blocks) {
  constexpr long long b = kSumBlock;
  const std::vector<long long> populations{1,         2,         b - 1,     b,         b + 1,     2 * b,
                                           2 * b + 7, 3 * b,     5 * b - 3, 5 * b,     7 * b,     7 * b + 1,
                                           8 * b + b / 2,        9 * b};
  for (long long n : populations)
    for (int ranks = 1; ranks <= 8; ++ranks) {
      const long long blocks = (n + b - 1) / b;
      long long next = 0, fewest = blocks, most = 0;
      for (int rank = 0; rank < ranks; ++rank) {
        const MemberRange range = own_members(static_cast<Eigen::Index>(n), rank, ranks);
        const long long first = std::min(n, first_block(blocks, rank, ranks) * b);
        const long long end = std::min(n, first_block(blocks, rank + 1, ranks) * b);
        BOOST_TEST(range.first == first, "N " << n << ", rank " << rank << " of " << ranks);
        BOOST_TEST(range.count == end - first, "N " << n << ", rank " << rank << " of " << ranks);
        BOOST_TEST(range.first == next, "N " << n << ", rank " << rank << " of " << ranks << ": not contiguous");
        BOOST_TEST(range.count >= 0);
        BOOST_TEST((range.first % b == 0 || range.count == 0), "N " << n << ", rank " << rank << ": off a block boundary");
        next = range.first + range.count;
        const long long held = (range.count + b - 1) / b;  // blocks, the short last one counted
        fewest = std::min(fewest, held);
        most = std::max(most, held);
      }
      BOOST_TEST(next == n, "N " << n << " on " << ranks << " ranks: covers [0, " << next << ")");
      BOOST_TEST(most - fewest <= 1, "N " << n << " on " << ranks << " ranks: " << fewest << " to " << most << " blocks");
    }
}

// The examples by hand: 7 blocks on 3 ranks are 2, 2, 3 (⌊7/3⌋ = 2, ⌊14/3⌋ = 4, 7); 5 blocks on
// 2 ranks 2 and 3; 3 blocks minus 100 members on 2 ranks: one block, then one and a short one.
BOOST_AUTO_TEST_CASE(shares_by_hand) {
  constexpr Eigen::Index b = kSumBlock;
  BOOST_TEST(own_members(7 * b, 0, 3).count == 2 * b);
  BOOST_TEST(own_members(7 * b, 1, 3).first == 2 * b);
  BOOST_TEST(own_members(7 * b, 1, 3).count == 2 * b);
  BOOST_TEST(own_members(7 * b, 2, 3).first == 4 * b);
  BOOST_TEST(own_members(7 * b, 2, 3).count == 3 * b);
  BOOST_TEST(own_members(5 * b, 1, 2).first == 2 * b);
  BOOST_TEST(own_members(5 * b, 1, 2).count == 3 * b);
  BOOST_TEST(own_members(3 * b - 100, 0, 2).count == b);
  BOOST_TEST(own_members(3 * b - 100, 1, 2).first == b);
  BOOST_TEST(own_members(3 * b - 100, 1, 2).count == 2 * b - 100);
}

BOOST_AUTO_TEST_SUITE_END()

}  // namespace unit_distribution
