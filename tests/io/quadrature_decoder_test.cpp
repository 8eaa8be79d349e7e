// The encoder decoder: clean turns both ways, contact bounce, missed edges.
#include "io/quadrature_decoder.hpp"

#include <gtest/gtest.h>

#include <utility>
#include <vector>

namespace puddle::io {
namespace {

using Levels = std::pair<bool, bool>;  // A, B

// One clockwise detent from rest 11: A falls first, then B, then A rises, then B.
const std::vector<Levels> clockwise{{false, true}, {false, false}, {true, false}, {true, true}};
const std::vector<Levels> counter_clockwise{{true, false}, {false, false}, {false, true}, {true, true}};

int feed(QuadratureDecoder& d, const std::vector<Levels>& seq) {
    int total = 0;
    for (auto [a, b] : seq) total += d.update(a, b);
    return total;
}

TEST(QuadratureDecoder, CleanTurnsCountOneDetentEachWay) {
    QuadratureDecoder d;
    d.reset(true, true);
    EXPECT_EQ(feed(d, clockwise), 1);
    EXPECT_EQ(feed(d, clockwise), 1);
    EXPECT_EQ(feed(d, counter_clockwise), -1);
}

TEST(QuadratureDecoder, WorksFromEitherRestState) {
    QuadratureDecoder d;
    d.reset(false, false);  // an encoder wired to idle low
    // From 00 clockwise: A rises first.
    EXPECT_EQ(feed(d, {{true, false}, {true, true}, {false, true}, {false, false}}), 1);
    EXPECT_EQ(feed(d, {{false, true}, {true, true}, {true, false}, {false, false}}), -1);
}

TEST(QuadratureDecoder, ContactBounceDoesNotAddOrLoseDetents) {
    QuadratureDecoder d;
    d.reset(true, true);
    // A bounces three times before settling low, B bounces when it falls; still one detent.
    const std::vector<Levels> bouncy{{false, true}, {true, true},   {false, true}, {true, true},
                                     {false, true}, {false, false}, {false, true}, {false, false},
                                     {true, false}, {true, true}};
    EXPECT_EQ(feed(d, bouncy), 1);
}

TEST(QuadratureDecoder, BounceAtRestIsNoDetent) {
    QuadratureDecoder d;
    d.reset(true, true);
    EXPECT_EQ(feed(d, {{false, true}, {true, true}, {true, false}, {true, true}}), 0);
}

TEST(QuadratureDecoder, AMissedEdgeStillGivesTheTurnButNeverTwo) {
    QuadratureDecoder d;
    d.reset(true, true);
    // 01 -> 10 changes both bits (an edge was lost): that transition counts nothing, the rest still
    // adds up to more than half a cycle, so the detent is reported once.
    EXPECT_EQ(feed(d, {{false, true}, {false, false}, {true, true}}), 1);
    // Only invalid jumps: no direction can be known, so no detent.
    EXPECT_EQ(feed(d, {{false, false}, {true, true}}), 0);
}

TEST(QuadratureDecoder, EveryTransitionOfTheTable) {
    // Valid single-bit changes move one quarter, two-bit changes nothing.
    const int codes[4][2] = {{0, 0}, {0, 1}, {1, 0}, {1, 1}};
    for (int from = 0; from < 4; ++from)
        for (int to = 0; to < 4; ++to) {
            QuadratureDecoder d;
            d.reset(codes[from][0] == 0, codes[from][1] == 0);  // a rest elsewhere, so no detent fires
            d.update(codes[from][0], codes[from][1]);
            const int before = d.quarter_steps();
            d.update(codes[to][0], codes[to][1]);
            const int moved = d.quarter_steps() - before;
            const int bits = (from ^ to) == 3 ? 2 : (from == to ? 0 : 1);
            if (bits == 1)
                EXPECT_EQ(std::abs(moved), 1) << from << "->" << to;
            else
                EXPECT_EQ(moved, 0) << from << "->" << to;
        }
}

}  // namespace
}  // namespace puddle::io
