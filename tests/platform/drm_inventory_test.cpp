// The DRM card list that the kms backend picks from and --check prints: the kernel's numbering order
// (card10 after card2), render nodes and other names left out.
#include "platform/drm_inventory.hpp"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

#include "platform/drm_names.hpp"
#include "support/test_support.hpp"

namespace puddle::platform {
namespace {

TEST(DrmInventory, CardsComeInTheKernelsNumberOrder) {
    test::TempDir dir;
    for (const char* name : {"card10", "card2", "renderD128", "card0", "cardx", "card1", "card", "by-path"})
        std::ofstream(dir / name) << "";
    const auto cards = drm_card_paths(dir.path().string());
    const std::string d = dir.path().string() + "/";
    EXPECT_EQ(cards, (std::vector<std::string>{d + "card0", d + "card1", d + "card2", d + "card10"}));
}

TEST(DrmInventory, AMissingFolderHasNoCards) {
    EXPECT_TRUE(drm_card_paths("/nonexistent-puddle-dri").empty());
}

// --check reads the status, not the message: a card without KMS outputs is no fault (a render-only GPU
// beside the display one), a card that cannot be opened is. A plain file stands in for the former (it
// answers no KMS resources either), a dangling link for a node that vanished.
TEST(DrmInventory, EachCardSaysWhetherItHasOutputsOrCouldNotBeOpened) {
    test::TempDir dir;
    std::ofstream(dir / "card10") << "";
    std::ofstream(dir / "card0") << "";
    std::filesystem::create_symlink(dir / "gone", dir / "card2");
    const auto cards = list_drm_cards(dir.path().string());
    ASSERT_EQ(cards.size(), 3u);
    const std::string d = dir.path().string() + "/";
    EXPECT_EQ(cards[0].path, d + "card0");
    EXPECT_EQ(cards[0].status, DrmCardStatus::NoOutputs);
    EXPECT_EQ(cards[0].error, "no display outputs (a render-only GPU)");
    EXPECT_TRUE(cards[0].connectors.empty());
    EXPECT_EQ(cards[1].path, d + "card2");
    EXPECT_EQ(cards[1].status, DrmCardStatus::CannotOpen);
    EXPECT_EQ(cards[1].error, "cannot open: No such file or directory");
    EXPECT_EQ(cards[2].path, d + "card10");
    EXPECT_EQ(cards[2].status, DrmCardStatus::NoOutputs);
}

TEST(DrmInventory, NamesAConnectorAndAModeAsTheKernelAndTheConfigDo) {
    drmModeConnector hdmi{};
    hdmi.connector_type = DRM_MODE_CONNECTOR_HDMIA;
    hdmi.connector_type_id = 1;
    EXPECT_EQ(connector_name(hdmi), "HDMI-A-1");
    drmModeModeInfo mode{};
    mode.hdisplay = 1920;
    mode.vdisplay = 1080;
    mode.vrefresh = 60;
    EXPECT_EQ(mode_name(mode), "1920x1080@60");
}

}  // namespace
}  // namespace puddle::platform
