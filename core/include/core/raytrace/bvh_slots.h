#pragma once
// The wide tree as a depth-first sequence of its nodes' slots, for tests and the bench that
// compare two builds (issue 21: the build that stops at the wide leaves against the collapse
// of the whole binary tree): boxes bit for bit, leaf ranges, inner children followed where
// they point, so two trees compare equal whatever the order of their nodes in the array.
#include "core/raytrace/bvh.h"

#include <cstdint>
#include <cstring>
#include <vector>

namespace wb::rt {

namespace detail {
template <class Node, class A>
void wideSlots(const std::vector<Node, A>& nodes, std::uint32_t i,
               std::vector<std::uint64_t>& out) {
    constexpr int W = sizeof(Node{}.child) / sizeof(std::uint32_t);
    const Node& n = nodes[i];
    for (int c = 0; c < W; ++c) {
        for (int a = 0; a < 3; ++a) {
            std::uint32_t lo, hi;
            std::memcpy(&lo, &n.lo[a][c], 4);
            std::memcpy(&hi, &n.hi[a][c], 4);
            out.push_back(std::uint64_t(lo) << 32 | hi);
        }
        const bool empty = !(n.lo[0][c] <= n.hi[0][c]);
        out.push_back(empty        ? 0xE
                      : n.count[c] ? std::uint64_t(n.count[c]) << 32 | n.child[c]
                                   : 0x1);
        if (!empty && n.count[c] == 0) wideSlots(nodes, n.child[c], out);
    }
}
} // namespace detail

// Both widths' trees (a Bvh holds one of them, or none for a plain loop).
inline std::vector<std::uint64_t> wideSlots(const Bvh& b) {
    std::vector<std::uint64_t> out;
    if (!b.wideNodes().empty()) detail::wideSlots(b.wideNodes(), 0, out);
    if (!b.wideNodes8().empty()) detail::wideSlots(b.wideNodes8(), 0, out);
    return out;
}

} // namespace wb::rt
