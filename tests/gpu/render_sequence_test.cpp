// `manylights render` for sequences, camera paths, orbits, video and per-frame timing: a
// sequence's frames are the single frames of the same numbers byte for byte, a path's frames are
// `render --camera` at the interpolated pose, and bad input is one line.
#include <gtest/gtest.h>

#include <algorithm>
#include <fstream>

#include "gpu_test.h"

namespace ml::test {
namespace {

const std::string kSmallFrame = "--scene boxes --detail 0.5 --size 160x90 --lights 64 --seed 3";

int countLines(const std::string& text) { return static_cast<int>(std::count(text.begin(), text.end(), '\n')); }

bool haveProgram(const std::string& name) { return std::system(("command -v " + name + " >/dev/null 2>&1").c_str()) == 0; }

// A fresh directory for one test's files.
std::string freshDir(const std::string& name) {
    const std::filesystem::path dir = testOutputDir() / name;
    std::filesystem::remove_all(dir);
    std::filesystem::create_directories(dir);
    return dir.string();
}

void expectSameImage(const std::string& a, const std::string& b) {
    const RgbaImage x = readPng(a), y = readPng(b);
    ASSERT_EQ(x.width, y.width);
    ASSERT_EQ(x.height, y.height);
    EXPECT_TRUE(x.pixels == y.pixels) << a << " and " << b << " differ; images in "
                                      << writeFailureImages(std::filesystem::path(a).stem().string(), x, y);
}

TEST(RenderSequence, FramesEqualSingleFrameRendersByteForByte) {
    const std::string dir = freshDir("sequence");
    std::string output;
    ASSERT_EQ(runManylights("render " + kSmallFrame + " --frames 3..5 --out " + dir + "/seq_%02d.png", output), 0) << output;
    EXPECT_NE(output.find("frames 3..5"), std::string::npos) << output;
    for (int k = 3; k <= 5; ++k) {
        const std::string single = dir + "/single_" + std::to_string(k) + ".png";
        ASSERT_EQ(runManylights("render " + kSmallFrame + " --frames " + std::to_string(k) + " --out " + single, output), 0) << output;
        expectSameImage(dir + "/seq_0" + std::to_string(k) + ".png", single);
    }
    // The frames differ from each other (the lights drift), so the comparison means something.
    EXPECT_NE(readPng(dir + "/seq_03.png").pixels, readPng(dir + "/seq_05.png").pixels);
}

TEST(RenderSequence, ExistingFilesAreKeptUnlessOverwriteIsGiven) {
    const std::string dir = freshDir("overwrite");
    const std::string args = "render " + kSmallFrame + " --frames 0..1 --out " + dir + "/f_%d.png";
    std::string output;
    ASSERT_EQ(runManylights(args, output), 0) << output;
    EXPECT_NE(runManylights(args, output), 0);
    EXPECT_EQ(countLines(output), 1) << output;
    EXPECT_NE(output.find("--overwrite"), std::string::npos) << output;
    EXPECT_EQ(runManylights(args + " --overwrite", output), 0) << output;
}

TEST(RenderSequence, CameraPathFramesEqualRenderCameraAtTheInterpolatedPose) {
    const std::string dir = freshDir("camera_path");
    {
        std::ofstream path(dir + "/path.json");
        path << R"({"keyframes": [
            {"frame": 0, "eye": [8, 8, 14],  "target": [0, 1, 0], "fovy": 50},
            {"frame": 4, "eye": [12, 8, 10], "target": [4, 1, 0], "fovy": 70}]})";
    }
    std::string output;
    ASSERT_EQ(runManylights("render " + kSmallFrame + " --frames 1..2 --camera-path " + dir + "/path.json --out " + dir +
                                "/path_%d.png",
                            output),
              0)
        << output;
    // A quarter and half of the way: poses exactly representable in floats.
    const char* poses[] = {"9,8,13,1,1,0,55", "10,8,12,2,1,0,60"};
    for (int k = 1; k <= 2; ++k) {
        const std::string single = dir + "/camera_" + std::to_string(k) + ".png";
        ASSERT_EQ(runManylights("render " + kSmallFrame + " --frames " + std::to_string(k) + " --camera " + poses[k - 1] +
                                    " --out " + single,
                                output),
                  0)
            << output;
        expectSameImage(dir + "/path_" + std::to_string(k) + ".png", single);
    }
}

TEST(RenderSequence, OrbitReturnsToItsStart) {
    const std::string dir = freshDir("orbit");
    std::string output;
    // Still lights: only the camera moves, so a full turn must give frame 0 again.
    ASSERT_EQ(runManylights("render " + kSmallFrame + " --drift-speed 0 --camera orbit:frames=4,elevation=30 --frames 0..4 --out " +
                                dir + "/orbit_%d.png",
                            output),
              0)
        << output;
    expectSameImage(dir + "/orbit_0.png", dir + "/orbit_4.png");
    EXPECT_NE(readPng(dir + "/orbit_0.png").pixels, readPng(dir + "/orbit_1.png").pixels) << "the camera should move";
    // A single frame of the orbit is the sequence's frame of that number.
    ASSERT_EQ(runManylights("render " + kSmallFrame + " --drift-speed 0 --camera orbit:frames=4,elevation=30 --frames 2 --out " +
                                dir + "/single_2.png",
                            output),
              0)
        << output;
    expectSameImage(dir + "/orbit_2.png", dir + "/single_2.png");
}

TEST(RenderSequence, TimingCsvHasARowPerFrameWithTheBenchColumns) {
    const std::string dir = freshDir("timing");
    std::string output;
    ASSERT_EQ(runManylights("render " + kSmallFrame + " --frames 10..12 --camera orbit --timing-csv " + dir + "/t.csv", output), 0)
        << output;
    std::ifstream in(dir + "/t.csv");
    std::string header, line;
    std::getline(in, header);
    for (const char* column : {"frame_index", "eye_x", "target_z", "fovy", "clock", "frame_ms", "wall_ms",
                               "pass_deferred_gbuffer_ms", "pass_tonemap_ms"})
        EXPECT_NE(header.find(column), std::string::npos) << column << " missing in " << header;
    std::vector<std::string> rows;
    while (std::getline(in, line)) rows.push_back(line);
    ASSERT_EQ(rows.size(), 3u);
    EXPECT_EQ(rows[0].rfind("10,", 0), 0u) << rows[0];
    EXPECT_EQ(rows[2].rfind("12,", 0), 0u) << rows[2];
    EXPECT_FALSE(std::filesystem::exists(dir + "/manylights.png")) << "a sequence writes PNGs only when asked";
}

TEST(RenderSequence, VideoIsAClipFfprobeReadsFrameByFrame) {
    if (!haveProgram("ffmpeg") || !haveProgram("ffprobe"))
        GTEST_SKIP() << "ffmpeg/ffprobe not found (apt-get install ffmpeg): the video tests need them";
    const std::string dir = freshDir("video");
    std::string output;
    ASSERT_EQ(runManylights("render " + kSmallFrame + " --frames 0..5 --video " + dir + "/clip.mp4 --video-fps 24", output), 0)
        << output;
    const std::string probe = "ffprobe -v error -count_frames -select_streams v:0 -show_entries "
                              "stream=nb_read_frames,width,height,codec_name -of default=noprint_wrappers=1 " +
                              dir + "/clip.mp4";
    FILE* pipe = popen(probe.c_str(), "r");
    ASSERT_NE(pipe, nullptr);
    std::string result;
    char buffer[256];
    while (std::fgets(buffer, sizeof buffer, pipe)) result += buffer;
    ASSERT_EQ(pclose(pipe), 0) << result;
    EXPECT_NE(result.find("nb_read_frames=6"), std::string::npos) << result;
    EXPECT_NE(result.find("width=160"), std::string::npos) << result;
    EXPECT_NE(result.find("codec_name=h264"), std::string::npos) << result;
}

TEST(RenderSequence, MissingFfmpegIsOneLineSayingHowToGetIt) {
    std::string output;
    // An empty PATH: no ffmpeg to find (the executable itself is run by its full path).
    EXPECT_NE(runManylights("render " + kSmallFrame + " --frames 0..2 --video /tmp/never.mp4", output, "", "env PATH="), 0);
    EXPECT_EQ(countLines(output), 1) << output;
    EXPECT_NE(output.find("apt-get install ffmpeg"), std::string::npos) << output;
}

struct BadSequence {
    const char* name;
    const char* args;     // @DIR@: a fresh directory holding a regular file "file" and a broken path.json
    const char* culprit;  // must appear in the one-line message
};

class RenderSequenceBadInput : public ::testing::TestWithParam<BadSequence> {};

TEST_P(RenderSequenceBadInput, FailsWithOneLineNamingTheCulprit) {
    const std::string dir = freshDir(std::string("bad_") + GetParam().name);
    std::ofstream(dir + "/file") << "not a directory";
    std::ofstream(dir + "/path.json") << R"({"keyframes": [{"frame": 0, "eye": [0, 1], "target": [0, 0, 0]}]})";
    std::string args = GetParam().args;
    for (std::size_t at; (at = args.find("@DIR@")) != std::string::npos;) args.replace(at, 5, dir);
    std::string output;
    EXPECT_NE(runManylights("render " + kSmallFrame + " " + args, output), 0) << output;
    EXPECT_NE(output.find(GetParam().culprit), std::string::npos) << output;
    EXPECT_EQ(countLines(output), 1) << output;
}

INSTANTIATE_TEST_SUITE_P(
    Inputs, RenderSequenceBadInput,
    ::testing::Values(
        BadSequence{"no_field", "--frames 0..2 --out @DIR@/frame.png", "frame-number field"},
        BadSequence{"two_fields", "--frames 0..2 --out @DIR@/f_%d_%04d.png", "more than one"},
        BadSequence{"other_field", "--frames 0..2 --out @DIR@/f_%s.png", "%s"},
        BadSequence{"float_no_field", "--frames 0..2 --out-float @DIR@/f.pfm", "--out-float"},
        BadSequence{"unwritable_directory", "--frames 0..2 --out @DIR@/file/f_%d.png", "cannot create the directory"},
        BadSequence{"field_in_directory", "--frames 0..2 --out @DIR@/d%d/f.png", "not in a directory"},
        BadSequence{"backwards_range", "--frames 5..2 --out @DIR@/f_%d.png", "--frames"},
        BadSequence{"not_a_range", "--frames 1-5 --out @DIR@/f_%d.png", "--frames"},
        BadSequence{"nothing_to_write", "--frames 0..2", "nothing to write"},
        BadSequence{"missing_path", "--frames 0..2 --camera-path @DIR@/nowhere.json --out @DIR@/f_%d.png", "nowhere.json"},
        BadSequence{"broken_path", "--frames 0..2 --camera-path @DIR@/path.json --out @DIR@/f_%d.png", "keyframe 0"},
        BadSequence{"path_and_camera", "--camera-path @DIR@/path.json --camera 1,2,3,0,0,0,60", "give one"},
        BadSequence{"orbit_zero_frames", "--camera orbit:frames=0", "frames"},
        BadSequence{"orbit_unknown_key", "--camera orbit:spin=3", "spin"},
        BadSequence{"orbit_not_a_number", "--camera orbit:elevation=high", "elevation"},
        BadSequence{"video_container", "--video @DIR@/clip.avi", "--video"},
        BadSequence{"video_crf", "--video @DIR@/clip.mp4 --video-crf 70", "--video-crf"}),
    [](const auto& info) { return std::string(info.param.name); });

}  // namespace
}  // namespace ml::test
