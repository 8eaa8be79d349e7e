// GlHandle (gpu/handle.hpp): the name it holds is deleted exactly once, by destruction, reset() or a
// move-assignment over it; a move leaves the source holding none; release() hands the name over without
// deleting it; name 0 is never deleted. A counting deleter stands in for glDelete*.
#include "gpu/handle.hpp"

#include <gtest/gtest.h>

#include <cstdint>
#include <type_traits>
#include <vector>

namespace puddle::gpu {
namespace {

// Every name the deleter was called with, in order.
std::vector<std::uint32_t>& deleted() {
    static std::vector<std::uint32_t> names;
    return names;
}
void record_delete(std::uint32_t id) {
    deleted().push_back(id);
}
using Handle = GlHandle<record_delete>;

class GlHandleTest : public ::testing::Test {
protected:
    void SetUp() override { deleted().clear(); }
};

static_assert(!std::is_copy_constructible_v<Handle> && !std::is_copy_assignable_v<Handle>);
static_assert(std::is_nothrow_move_constructible_v<Handle> && std::is_nothrow_move_assignable_v<Handle>);

TEST_F(GlHandleTest, AnEmptyHandleHoldsZeroAndDeletesNothing) {
    {
        const Handle empty;
        EXPECT_EQ(empty.get(), 0u);
        EXPECT_FALSE(empty);
        const Handle zero(0);
        EXPECT_FALSE(zero);
    }
    EXPECT_TRUE(deleted().empty());
}

TEST_F(GlHandleTest, DestructionDeletesTheNameOnce) {
    {
        const Handle h(7);
        EXPECT_EQ(h.get(), 7u);
        EXPECT_TRUE(h);
        EXPECT_TRUE(deleted().empty()) << "nothing is deleted while the handle lives";
    }
    EXPECT_EQ(deleted(), std::vector<std::uint32_t>{7});
}

TEST_F(GlHandleTest, AMoveHandsTheNameOverAndTheSourceHoldsNone) {
    {
        Handle a(3);
        Handle b(std::move(a));
        EXPECT_EQ(a.get(), 0u);  // NOLINT(bugprone-use-after-move): the moved-from state is the contract
        EXPECT_EQ(b.get(), 3u);
        EXPECT_TRUE(deleted().empty());
    }
    EXPECT_EQ(deleted(), std::vector<std::uint32_t>{3}) << "deleted once, by the new owner";
}

TEST_F(GlHandleTest, MoveAssignmentDeletesTheNameItReplaces) {
    Handle target(1);
    Handle source(2);
    target = std::move(source);
    EXPECT_EQ(deleted(), std::vector<std::uint32_t>{1}) << "the old name goes at once";
    EXPECT_EQ(target.get(), 2u);
    EXPECT_EQ(source.get(), 0u);  // NOLINT(bugprone-use-after-move)
    target = Handle();
    EXPECT_EQ(deleted(), (std::vector<std::uint32_t>{1, 2}));
    EXPECT_FALSE(target);
}

TEST_F(GlHandleTest, SelfMoveAssignmentKeepsTheName) {
    Handle h(9);
    Handle& alias = h;
    h = std::move(alias);
    EXPECT_EQ(h.get(), 9u);
    EXPECT_TRUE(deleted().empty());
}

TEST_F(GlHandleTest, ReleaseHandsTheNameOverWithoutDeletingIt) {
    {
        Handle h(5);
        EXPECT_EQ(h.release(), 5u);
        EXPECT_EQ(h.get(), 0u);
        EXPECT_EQ(h.release(), 0u) << "a second release has nothing left";
    }
    EXPECT_TRUE(deleted().empty());
}

TEST_F(GlHandleTest, ResetDeletesOnceAndLeavesTheHandleEmpty) {
    Handle h(4);
    h.reset();
    EXPECT_EQ(deleted(), std::vector<std::uint32_t>{4});
    EXPECT_FALSE(h);
    h.reset();
    EXPECT_EQ(deleted(), std::vector<std::uint32_t>{4}) << "a second reset deletes nothing";
}

}  // namespace
}  // namespace puddle::gpu
