#include "harness/distribution.hpp"

#include <algorithm>
#include <cmath>

#include "harness/compensated_sum.hpp"

namespace dlpverify {

namespace {

class Serial final : public Distribution {
 public:
  int rank() const override { return 0; }
  int ranks() const override { return 1; }
  std::vector<double> all_gathered(const std::vector<double>& local) const override { return local; }
  State gathered_on_root(const State& local) const override { return local; }
  std::string from_root(const std::string& text) const override { return text; }
};

const Serial kSerial;
const Distribution* installed = nullptr;

}  // namespace

double Distribution::max(double local) const {
  double largest = -INFINITY;
  for (double x : all_gathered({local})) {
    if (std::isnan(x)) return x;
    if (x > largest) largest = x;
  }
  return largest;
}

// Counts travel as doubles: exact below 2^53.
long Distribution::sum(long local) const {
  long total = 0;
  for (double x : all_gathered({static_cast<double>(local)})) total += static_cast<long>(x);
  return total;
}

long Distribution::max(long local) const {
  long largest = local;
  for (double x : all_gathered({static_cast<double>(local)})) largest = std::max(largest, static_cast<long>(x));
  return largest;
}

bool Distribution::any(bool local) const { return sum(local ? 1L : 0L) > 0; }

const Distribution& distribution() { return installed ? *installed : kSerial; }

void install_distribution(const Distribution* d) { installed = d; }

MemberRange own_members(Eigen::Index members, int rank, int ranks) {
  const Eigen::Index blocks = (members + kSumBlock - 1) / kSumBlock;
  const Eigen::Index first_block = blocks * rank / ranks, end_block = blocks * (rank + 1) / ranks;
  MemberRange range;
  range.first = std::min(members, first_block * kSumBlock);
  range.count = std::min(members, end_block * kSumBlock) - range.first;
  return range;
}

MemberRange own_members(Eigen::Index members) {
  return own_members(members, distribution().rank(), distribution().ranks());
}

}  // namespace dlpverify
