#include "harness/rank_share.hpp"

#include "harness/distribution.hpp"

namespace dlpverify {

RankShare::RankShare(const Problem& whole) : whole_(whole) {
  if (distribution().ranks() == 1) return;
  const MemberRange own = own_members(whole.members());
  slab_.emplace(whole, own.first, own.count);
}

}  // namespace dlpverify
