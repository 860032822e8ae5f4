#include "hotlap/track/track_io.h"

#include <cstdlib>
#include <string>

#include <gtest/gtest.h>

#include "hotlap/common/data_path.h"
#include "hotlap/common/error.h"
#include "test_util.h"

namespace hotlap::track {
namespace {

using test::Contains;

TEST(TrackIoTest, BuiltInNamesResolveToDataTracks) {
  EXPECT_EQ(ResolveTrackFile("darlington"), DataDir() / "tracks" / "darlington.yaml");
  EXPECT_EQ(ResolveTrackFile("catalunya-fl"), DataDir() / "tracks" / "catalunya-fl.xml");
  EXPECT_EQ(ResolveTrackFile("ims"), DataDir() / "tracks" / "ims.csv");
  const auto path = test::SourcePath("data/tracks/ims.csv");
  EXPECT_EQ(ResolveTrackFile(path.string()), path);  // a path is taken as it is
}

TEST(TrackIoTest, UnknownNameListsTheBuiltIns) {
  try {
    ResolveTrackFile("darlingtn");
    FAIL() << "no error";
  } catch (const InputError& e) {
    EXPECT_TRUE(Contains(e.what(), "no track 'darlingtn'"));
    EXPECT_TRUE(Contains(e.what(), "'catalunya', 'catalunya-fl', 'darlington' or 'ims'"))
        << e.what();
  }
}

TEST(TrackIoTest, LoadsEveryFormatByExtension) {
  const TrackFile d = LoadTrackByName("darlington");
  EXPECT_EQ(d.format, TrackFormat::kSegments);
  EXPECT_EQ(d.segments.size(), 8u);
  EXPECT_EQ(d.solved.size(), 4u);
  const TrackFile c = LoadTrackByName("catalunya");
  EXPECT_EQ(c.format, TrackFormat::kTumCsv);
  EXPECT_TRUE(c.segments.empty());
  EXPECT_EQ(LoadTrackByName("catalunya-fl").format, TrackFormat::kFastestLapXml);
  EXPECT_EQ(std::string(TrackFormatName(TrackFormat::kFastestLapXml)), "fastest-lap-xml");
  EXPECT_EQ(LoadTrack("ims").name(), "ims");
}

TEST(TrackIoTest, UnknownExtensionIsAnError) {
  test::TempDir dir;
  const auto path = dir.Write("track.txt", "x");
  try {
    LoadTrackByName(path.string());
    FAIL() << "no error";
  } catch (const InputError& e) {
    EXPECT_TRUE(Contains(e.what(), "unknown track file type '.txt'"));
    EXPECT_TRUE(Contains(e.what(), ".yaml or .yml (segments), .csv"));
  }
}

}  // namespace
}  // namespace hotlap::track
