// Image files: PNG/PFM round trips, the PFM header, the independent reference
// images (tests/data/reference-images/), and the atomic-write guarantees of docs/spec.md#8-command-line.
#include "image/image.h"
#include "image/quantize.h"
#include "test_support.h"

#include <gtest/gtest.h>

#include <sys/stat.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <filesystem>
#include <string>

namespace m3055 {
namespace {

using test::TempDir;
namespace fs = std::filesystem;

Rgb8Image gradient_rgb8(int width, int height) {
    Rgb8Image image{width, height, {}};
    for (int y = 0; y < height; ++y)
        for (int x = 0; x < width; ++x) {
            image.pixels.push_back(std::uint8_t((x * 37 + y) & 0xff));
            image.pixels.push_back(std::uint8_t((y * 91 + 3 * x) & 0xff));
            image.pixels.push_back(std::uint8_t((x ^ y) & 0xff));
        }
    return image;
}

RgbFloatImage varied_float(int width, int height) {
    RgbFloatImage image{width, height, {}};
    for (int i = 0; i < width * height * 3; ++i)
        image.pixels.push_back(float(std::sin(0.37 * i) * 3.0 + (i % 5 == 0 ? 1e-7 : 0.0)));
    image.pixels[0] = 12345.678f;  // unclamped values must survive
    image.pixels[1] = -0.25f;
    return image;
}

std::string reference_image(const std::string& name) { return test::reference_image_path(name); }

std::vector<std::string> folder_entries(const std::string& folder) {
    std::vector<std::string> names;
    for (const auto& entry : fs::directory_iterator(folder)) names.push_back(entry.path().filename());
    std::sort(names.begin(), names.end());
    return names;
}

TEST(Png, RoundTripIsExact) {
    TempDir dir;
    const Rgb8Image original = gradient_rgb8(37, 11);  // odd sizes catch stride mistakes
    write_png(dir.file("a.png"), original);
    const Rgb8Image back = read_png(dir.file("a.png"));
    EXPECT_EQ(back.width, 37);
    EXPECT_EQ(back.height, 11);
    EXPECT_EQ(back.pixels, original.pixels);
}

TEST(Png, EncodingIsDeterministicAndPixelSensitive) {
    Rgb8Image image = gradient_rgb8(64, 40);
    const auto first = encode_png(image);
    EXPECT_EQ(encode_png(image), first);
    image.pixels[5] ^= 1;
    EXPECT_NE(encode_png(image), first);
}

TEST(Png, FirstRowIsTopRow) {
    // 1x2 image: the top pixel red, the bottom one blue; stb reads top row first too,
    // so this checks that nothing flips rows on the way.
    const Rgb8Image image{1, 2, {255, 0, 0, 0, 0, 255}};
    TempDir dir;
    write_png(dir.file("t.png"), image);
    EXPECT_EQ(read_png(dir.file("t.png")).pixels, image.pixels);
}

TEST(Png, RejectsMismatchedBufferAndMissingFile) {
    Rgb8Image bad{4, 4, std::vector<std::uint8_t>(10)};
    EXPECT_THROW(encode_png(bad), ImageError);
    TempDir dir;
    try {
        read_png(dir.file("missing.png"));
        FAIL() << "expected ImageError";
    } catch (const ImageError& e) {
        EXPECT_NE(std::string(e.what()).find("missing.png"), std::string::npos) << e.what();
    }
}

TEST(Pfm, HeaderBytesAndLittleEndianRasterAreExact) {
    const RgbFloatImage image{2, 1, {1.0f, 0.5f, -2.0f, 0.0f, 0.25f, 3.0f}};
    const auto bytes = encode_pfm(image);
    const std::string header = "PF\n2 1\n-1.0\n";
    ASSERT_EQ(bytes.size(), header.size() + 6 * 4);
    EXPECT_EQ(std::string(bytes.begin(), bytes.begin() + long(header.size())), header);
    // 1.0f little-endian is 00 00 80 3f; -2.0f is 00 00 00 c0.
    const std::uint8_t one[4] = {0x00, 0x00, 0x80, 0x3f};
    const std::uint8_t minus_two[4] = {0x00, 0x00, 0x00, 0xc0};
    EXPECT_EQ(std::memcmp(bytes.data() + header.size(), one, 4), 0);
    EXPECT_EQ(std::memcmp(bytes.data() + header.size() + 8, minus_two, 4), 0);
}

TEST(Pfm, RoundTripIsExactAndKeepsRowOrder) {
    TempDir dir;
    const RgbFloatImage original = varied_float(13, 7);
    write_pfm(dir.file("a.pfm"), original);
    const RgbFloatImage back = read_pfm(dir.file("a.pfm"));
    EXPECT_EQ(back.width, 13);
    EXPECT_EQ(back.height, 7);
    ASSERT_EQ(back.pixels.size(), original.pixels.size());
    EXPECT_EQ(std::memcmp(back.pixels.data(), original.pixels.data(), original.pixels.size() * 4), 0);
    EXPECT_EQ(encode_pfm(original), encode_pfm(original));
}

TEST(Pfm, ReadsBigEndianFiles) {
    TempDir dir;
    std::string text = "PF\n1 1\n1.0\n";
    const std::uint8_t raster[12] = {0x3f, 0x80, 0, 0, 0xc0, 0, 0, 0, 0x3e, 0x80, 0, 0};  // 1, -2, 0.25
    text.append(reinterpret_cast<const char*>(raster), 12);
    test::write_text(dir.file("be.pfm"), text);
    const RgbFloatImage image = read_pfm(dir.file("be.pfm"));
    ASSERT_EQ(image.pixels.size(), 3u);
    EXPECT_EQ(image.pixels[0], 1.0f);
    EXPECT_EQ(image.pixels[1], -2.0f);
    EXPECT_EQ(image.pixels[2], 0.25f);
}

TEST(Pfm, RejectsMalformedFilesNamingThePath) {
    TempDir dir;
    const std::string good_raster(12, '\0');
    const std::vector<std::string> bad = {
        "",                                       // empty
        "P6\n1 1\n255\n" + good_raster,           // a PPM
        "PF\n1\n-1.0\n" + good_raster,            // missing height
        "PF\n0 1\n-1.0\n",                        // zero width
        "PF\n1 1\n0\n" + good_raster,             // zero scale
        "PF\n1 1\nabc\n" + good_raster,           // scale not a number
        "PF\n2 1\n-1.0\n" + good_raster,          // raster too short
        "PF\n1 1\n-1.0\n" + good_raster + "xx",   // trailing bytes
    };
    for (std::size_t i = 0; i < bad.size(); ++i) {
        const std::string path = dir.file("bad" + std::to_string(i) + ".pfm");
        test::write_text(path, bad[i]);
        try {
            read_pfm(path);
            ADD_FAILURE() << "case " << i << " was accepted";
        } catch (const ImageError& e) {
            EXPECT_EQ(std::string(e.what()).rfind(path + ": not a PFM file: ", 0), 0u)
                << "case " << i << ": " << e.what();
        }
    }
    EXPECT_THROW(read_pfm(dir.file("missing.pfm")), ImageError);
}

TEST(ReferenceImages, SpecExamplePfmMatchesItsPng) {
    const RgbFloatImage raw = read_pfm(reference_image("spec_example.pfm"));
    ASSERT_EQ(raw.width, 512);
    ASSERT_EQ(raw.height, 320);
    for (const float v : raw.pixels) ASSERT_TRUE(std::isfinite(v));

    // The PNG is the 5-bit quantization of the PFM with rows flipped (PFM is
    // bottom to top). Only pixels sitting on a level boundary may differ, by one level.
    const Rgb8Image png = read_png(reference_image("spec_example.png"));
    ASSERT_EQ(png.width, 512);
    ASSERT_EQ(png.height, 320);
    int differing = 0, lit = 0;
    for (int y = 0; y < 320; ++y)
        for (int x = 0; x < 512; ++x)
            for (int c = 0; c < 3; ++c) {
                const float value = raw.pixels[(std::size_t(319 - y) * 512 + x) * 3 + c];
                const int expected = level_to_png(quantize_level(value, 5), 5);
                const int actual = png.pixels[(std::size_t(y) * 512 + x) * 3 + c];
                if (actual > 0) ++lit;
                if (actual != expected) {
                    ++differing;
                    EXPECT_LE(std::abs(actual - expected), 9) << x << "," << y;  // one 5-bit level = 8.2
                }
            }
    EXPECT_GT(lit, 10000);  // the sphere is there
    EXPECT_LT(differing, 50);
}

TEST(AtomicWrite, ReplacesAnExistingFileWithMode0644) {
    TempDir dir;
    const std::string path = dir.file("out.bin");
    test::write_text(path, "old contents that are longer than the new ones");
    write_file_atomic(path, "new", 3);
    EXPECT_EQ(test::read_text(path), "new");
    struct stat info {};
    ASSERT_EQ(::stat(path.c_str(), &info), 0);
    EXPECT_EQ(info.st_mode & 0777, 0644u);
    EXPECT_EQ(folder_entries(dir.path()), std::vector<std::string>{"out.bin"});
}

TEST(AtomicWrite, WritesLargeAndEmptyFiles) {
    TempDir dir;
    std::string big(5 << 20, 'x');
    for (std::size_t i = 0; i < big.size(); i += 4097) big[i] = char(i & 0x7f);
    write_file_atomic(dir.file("big"), big.data(), big.size());
    EXPECT_EQ(test::read_text(dir.file("big")), big);
    write_file_atomic(dir.file("empty"), "", 0);
    EXPECT_TRUE(test::file_exists(dir.file("empty")));
    EXPECT_EQ(test::read_text(dir.file("empty")), "");
}

TEST(AtomicWrite, MissingFolderThrowsNamingThePath) {
    TempDir dir;
    const std::string path = dir.file("no-such-folder/x.png");
    try {
        write_file_atomic(path, "abc", 3);
        FAIL() << "expected ImageError";
    } catch (const ImageError& e) {
        EXPECT_EQ(std::string(e.what()), path + ": cannot write into its folder: No such file or directory");
    }
    EXPECT_EQ(folder_entries(dir.path()), std::vector<std::string>{});
}

TEST(AtomicWrite, FailureLeavesOldFileAndNoTemporary) {
    // Tests may run as root, for whom permission bits do not stop a write. A
    // rename onto an existing non-empty folder fails for everyone, after the
    // temporary file exists: the last step failing is the hardest case.
    TempDir dir;
    const std::string target = dir.file("image.png");
    fs::create_directory(target);
    test::write_text(target + "/keep", "precious");
    try {
        write_file_atomic(target, "new", 3);
        FAIL() << "expected ImageError";
    } catch (const ImageError& e) {
        EXPECT_EQ(std::string(e.what()).rfind(target + ": ", 0), 0u) << e.what();
    }
    EXPECT_EQ(test::read_text(target + "/keep"), "precious");
    EXPECT_EQ(folder_entries(dir.path()), std::vector<std::string>{"image.png"});
}

TEST(AtomicWrite, ParentIsAFileThrowsAndKeepsTheFile) {
    TempDir dir;
    const std::string parent = dir.file("plain");
    test::write_text(parent, "old bytes\n\x01\x02");
    const std::string path = parent + "/x.pfm";
    try {
        write_pfm(path, RgbFloatImage{1, 1, {0.f, 0.f, 0.f}});
        FAIL() << "expected ImageError";
    } catch (const ImageError& e) {
        EXPECT_EQ(std::string(e.what()), path + ": cannot write into its folder: Not a directory");
    }
    EXPECT_EQ(test::read_text(parent), "old bytes\n\x01\x02");
    EXPECT_EQ(folder_entries(dir.path()), std::vector<std::string>{"plain"});
}

TEST(AtomicWrite, WritePngFailureKeepsOldPngByteIdentical) {
    TempDir dir;
    const std::string path = dir.file("shot.png");
    write_png(path, gradient_rgb8(8, 8));
    const std::string before = test::read_text(path);
    // A mismatched buffer fails before anything is written.
    EXPECT_THROW(write_png(path, Rgb8Image{8, 8, {}}), ImageError);
    EXPECT_EQ(test::read_text(path), before);
    EXPECT_EQ(folder_entries(dir.path()), std::vector<std::string>{"shot.png"});
}

}  // namespace
}  // namespace m3055
