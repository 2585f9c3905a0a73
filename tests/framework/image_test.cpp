// Image files: round trips through PNG, PPM and PFM, the 8-bit encoding, and
// malformed or unwritable files reported as ImageError rather than crashes.
#include "whitted/image.hpp"
#include "whitted/image_pictures.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <limits>
#include <string>

using namespace whitted;
namespace fs = std::filesystem;

namespace {

/// A fresh directory per test (tests run in parallel processes), removed afterwards.
class ImageFiles : public ::testing::Test {
  protected:
    void SetUp() override {
        const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
        dir_ = fs::temp_directory_path() / (std::string("whitted_image_") + info->name());
        fs::remove_all(dir_);
        fs::create_directories(dir_);
    }
    void TearDown() override { fs::remove_all(dir_); }

    /// A path inside the test's directory.
    fs::path file(const std::string& name) const { return dir_ / name; }

    /// Writes raw bytes, for hand-made (often broken) files.
    fs::path raw(const std::string& name, const std::string& bytes) const {
        std::ofstream(file(name), std::ios::binary) << bytes;
        return file(name);
    }

    /// The file's bytes.
    std::string bytes_of(const fs::path& path) const {
        std::ifstream in(path, std::ios::binary);
        return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
    }

    fs::path dir_;
};

/// A 3 x 2 image whose every pixel differs, so a flipped or transposed copy cannot pass.
Image test_image() {
    Image image(3, 2);
    const double values[] = {0.0, 0.25, 0.5, 0.75, 1.0, 0.125, 2.5, -1.0, 0.0625};
    for (int i = 0; i < 6; ++i) image.pixels[i] = Color(values[i], values[(i + 3) % 9], values[(i + 5) % 9]);
    return image;
}

/// Expects the 8-bit round trip of every component: to_byte(v) / 255.
void expect_quantised(const Image& read, const Image& written) {
    ASSERT_EQ(read.width, written.width);
    ASSERT_EQ(read.height, written.height);
    for (std::size_t i = 0; i < written.pixels.size(); ++i) {
        for (int k = 0; k < 3; ++k) {
            EXPECT_EQ(read.pixels[i][k], to_byte(written.pixels[i][k], Encoding::linear) / 255.0) << i << "," << k;
        }
    }
}

/// Expects read_image to throw an ImageError whose message starts with the path and mentions `reason`.
void expect_error(const fs::path& path, const std::string& reason) {
    try {
        read_image(path);
        ADD_FAILURE() << "no ImageError for " << path;
    } catch (const ImageError& error) {
        const std::string message = error.what();
        EXPECT_EQ(message.rfind(path.string() + ": ", 0), 0u) << message;
        EXPECT_NE(message.find(reason), std::string::npos) << message;
    }
}

} // namespace

TEST(ToByte, LinearEncodingRoundsHalfwayUp) {
    // 0.5 * 255 = 127.5 -> 128; 1 / 255 stays 1.
    EXPECT_EQ(to_byte(0.5, Encoding::linear), 128);
    EXPECT_EQ(to_byte(1.0 / 255.0, Encoding::linear), 1);
    EXPECT_EQ(to_byte(1.0, Encoding::linear), 255);
}

TEST(ToByte, ClampsOutOfRangeValuesAndNaN) {
    EXPECT_EQ(to_byte(-0.5, Encoding::linear), 0);
    EXPECT_EQ(to_byte(2.0, Encoding::srgb), 255);
    EXPECT_EQ(to_byte(std::nan(""), Encoding::srgb), 0);
}

TEST(ToByte, SrgbEncodingMatchesTheStandardCurve) {
    // 1.055 * 0.5^(1/2.4) - 0.055 = 0.735357; * 255 = 187.52 -> 188.
    EXPECT_EQ(to_byte(0.5, Encoding::srgb), 188);
    // Linear segment below 0.0031308: 12.92 * 0.002 * 255 = 6.59 -> 7 (the power curve would give 6).
    EXPECT_EQ(to_byte(0.002, Encoding::srgb), 7);
    // At the boundary both pieces give 0.04045, * 255 = 10.31 -> 10, on either side of it.
    EXPECT_EQ(to_byte(0.0031308, Encoding::srgb), 10);
    EXPECT_EQ(to_byte(0.0031309, Encoding::srgb), 10);
    EXPECT_EQ(to_byte(0.0, Encoding::srgb), 0);
}

TEST_F(ImageFiles, PfmRoundTripIsExactForFloats) {
    const Image image = test_image();
    write_image(image, file("a.pfm"));
    const Image read = read_image(file("a.pfm"));
    ASSERT_EQ(read.width, 3);
    ASSERT_EQ(read.height, 2);
    for (std::size_t i = 0; i < image.pixels.size(); ++i) {
        for (int k = 0; k < 3; ++k) EXPECT_EQ(read.pixels[i][k], static_cast<float>(image.pixels[i][k]));
    }
}

TEST_F(ImageFiles, PfmStoresLittleEndianRowsBottomFirst) {
    // Header "PF\n3 2\n-1.0\n", then the first float is the red of the bottom-left pixel (0, 1).
    Image image(3, 2);
    image.at(0, 1) = Color(0.75, 0, 0);
    write_image(image, file("b.pfm"));
    const std::string bytes = bytes_of(file("b.pfm"));
    const std::string header = "PF\n3 2\n-1.0\n";
    ASSERT_EQ(bytes.size(), header.size() + 3 * 2 * 3 * 4);
    EXPECT_EQ(bytes.substr(0, header.size()), header);
    // 0.75f = 0x3F400000, little-endian: 00 00 40 3F.
    EXPECT_EQ(bytes.substr(header.size(), 4), std::string("\x00\x00\x40\x3F", 4));
}

TEST_F(ImageFiles, PpmRoundTripQuantisesToEightBits) {
    const Image image = test_image();
    write_image(image, file("a.ppm"));
    const std::string bytes = bytes_of(file("a.ppm"));
    EXPECT_EQ(bytes.substr(0, 11), "P6\n3 2\n255\n");
    EXPECT_EQ(static_cast<unsigned char>(bytes[11 + 1]), 191); // top-left green 0.75 -> 191.25 -> 191
    expect_quantised(read_image(file("a.ppm")), image);
}

TEST_F(ImageFiles, PngRoundTripQuantisesToEightBits) {
    const Image image = test_image();
    write_image(image, file("a.png"));
    expect_quantised(read_image(file("a.png")), image);
}

TEST_F(ImageFiles, ExtensionsAreCaseInsensitive) {
    write_image(test_image(), file("UPPER.PNG"), Encoding::srgb);
    const Image read = read_image(file("UPPER.PNG"));
    EXPECT_EQ(read.pixels[2].x, to_byte(0.5, Encoding::srgb) / 255.0);
}

TEST_F(ImageFiles, UnknownExtensionNamesThePathAndTheAcceptedOnes) {
    try {
        write_image(test_image(), file("a.jpg"));
        FAIL() << "no ImageError";
    } catch (const ImageError& error) {
        const std::string message = error.what();
        EXPECT_NE(message.find(file("a.jpg").string()), std::string::npos) << message;
        EXPECT_NE(message.find(".png"), std::string::npos) << message;
        EXPECT_NE(message.find(".pfm"), std::string::npos) << message;
    }
    EXPECT_FALSE(fs::exists(file("a.jpg")));
    expect_error(raw("b.bmp", "BM"), "unknown image extension");
}

TEST_F(ImageFiles, NonFinitePixelsAreCountedAndNeverWritten) {
    Image image = test_image();
    image.pixels[0].x = std::nan("");
    image.pixels[3].z = std::numeric_limits<double>::infinity();
    image.pixels[4] = Color(-std::numeric_limits<double>::infinity());
    EXPECT_EQ(count_non_finite(image), 3u);
    for (const char* name : {"n.png", "n.ppm", "n.pfm"}) {
        try {
            write_image(image, file(name));
            ADD_FAILURE() << "no ImageError for " << name;
        } catch (const ImageError& error) {
            EXPECT_NE(std::string(error.what()).find("3 pixel"), std::string::npos) << error.what();
        }
        EXPECT_FALSE(fs::exists(file(name))) << name;
    }
}

TEST_F(ImageFiles, WritingIntoAMissingDirectoryFails) {
    EXPECT_THROW(write_image(test_image(), file("missing/a.ppm")), ImageError);
    EXPECT_THROW(write_image(test_image(), file("missing/a.png")), ImageError);
    EXPECT_THROW(write_image(test_image(), file("missing/a.pfm")), ImageError);
    expect_error(file("missing/a.ppm"), "no such file");
}

TEST_F(ImageFiles, AsciiPpmWithCommentsAndSmallMaxvalReadsAsFractions) {
    // maxval 4: samples 0..4 become v / 4.
    const Image image = read_image(raw("a.ppm", "P3 # ascii\n# size next\n2 1\n4\n0 1 2 # first\n3 4 4\n"));
    ASSERT_EQ(image.width, 2);
    EXPECT_EQ(image.pixels[0], Color(0.0, 0.25, 0.5));
    EXPECT_EQ(image.pixels[1], Color(0.75, 1.0, 1.0));
}

TEST_F(ImageFiles, SixteenBitBinaryPpmIsBigEndian) {
    // maxval 1000 > 255: two bytes per sample, 0x01F4 = 500 -> 0.5; 0x03E8 = 1000 -> 1.
    const std::string data("\x01\xF4\x03\xE8\x00\x00", 6);
    const Image image = read_image(raw("a.ppm", "P6\n1 1\n1000\n" + data));
    EXPECT_EQ(image.pixels[0], Color(0.5, 1.0, 0.0));
}

TEST_F(ImageFiles, BinaryPpmMayHaveACommentRightAfterMaxval) {
    // "255# note\n": the comment runs to the newline, which is the single byte that ends the header.
    const Image image = read_image(raw("a.ppm", "P6 1 1 255# note\n" + std::string("\xFF\x00\x33", 3)));
    EXPECT_EQ(image.pixels[0], Color(1.0, 0.0, 0.2));
}

TEST_F(ImageFiles, BigEndianGreyscalePfmFillsAllChannels) {
    // "Pf", positive scale: big-endian; 2 x 1, 0.5f = 3F 00 00 00, 2.0f = 40 00 00 00.
    const Image image = read_image(raw("a.pfm", std::string("Pf\n2 1\n1.0\n") + std::string("\x3F\0\0\0\x40\0\0\0", 8)));
    EXPECT_EQ(image.pixels[0], Color(0.5));
    EXPECT_EQ(image.pixels[1], Color(2.0));
}

TEST_F(ImageFiles, MalformedFilesGiveImageErrorsThatSayWhy) {
    expect_error(file("absent.ppm"), "absent.ppm: no such file");
    expect_error(raw("empty.ppm", ""), "empty");
    expect_error(raw("magic.ppm", "P5\n1 1\n255\nabc"), "magic");
    expect_error(raw("magic.pfm", "PX\n1 1\n-1.0\n" + std::string(12, '\0')), "magic");
    expect_error(raw("short.ppm", "P6\n2 2\n255\n12345"), "truncated");
    expect_error(raw("short.pfm", "PF\n2 2\n-1.0\n" + std::string(47, '\0')), "truncated");
    expect_error(raw("header.ppm", "P6\n2"), "truncated");
    expect_error(raw("zero.ppm", "P6\n0 1\n255\n"), "width");
    expect_error(raw("huge.ppm", "P6\n40000 40000\n255\n"), "width");
    // 32768 x 32768 is within the per-side limit but over 2^26 pixels: refused before any allocation.
    expect_error(raw("huge.pfm", "PF\n32768 32768\n-1.0\n1234"), "more than the 67108864 pixels allowed");
    expect_error(raw("long.pfm", "PF\n8193 8192\n-1.0\n1234"), "more than the 67108864 pixels allowed");
    // 0x7FC00000 is a float NaN, 0x7F800000 infinity (big-endian, scale 1.0).
    expect_error(raw("nan.pfm", std::string("Pf\n2 1\n1.0\n") + std::string("\x3F\0\0\0\x7F\xC0\0\0", 8)),
                 "pixel (1, 0) is not a finite number");
    expect_error(raw("inf.pfm", std::string("Pf\n1 1\n1.0\n") + std::string("\x7F\x80\0\0", 4)), "not a finite number");
    expect_error(raw("maxval.ppm", "P6\n1 1\n70000\n123456"), "maxval");
    expect_error(raw("sample.ppm", "P3\n1 1\n4\n1 2 5\n"), "exceeds maxval");
    expect_error(raw("scale.pfm", "PF\n1 1\n0.0\n" + std::string(12, '\0')), "scale");
    expect_error(raw("text.ppm", "P3\n1 1\n255\n1 two 3\n"), "sample");
    // Found by fuzzing: bytes that are not printable ASCII are shown as \xNN, and a long word is cut.
    expect_error(raw("bytes.ppm", "P3\n1 1\n255\n2\xff\x01" + std::string(100, '5') + " 0 0\n"),
                 "bad sample '2\\xff\\x01" + std::string(57, '5') + "...' (expected 0..65535)");
    expect_error(raw("bad.png", "not a png at all"), "PNG");
    expect_error(raw("cut.png", std::string("\x89PNG\r\n\x1a\n\0\0\0\x0dIHDR", 16)), "PNG");
    // Found by fuzzing: a chunk that claims more bytes than the file holds is refused before stb allocates them.
    expect_error(raw("claims.png", std::string("\x89PNG\r\n\x1a\n\x7f\xff\xff\xffIDAT", 16) + std::string(20, 'x')),
                 "corrupt PNG: chunk 'IDAT' claims 2147483647 bytes, the file has 20 left");
    expect_error(dir_, "is a directory");
    fs::create_directory(file("folder.ppm"));
    expect_error(file("folder.ppm"), "directory");
}

TEST_F(ImageFiles, TruncatedPngFromARealFileIsRejected) {
    write_image(test_image(), file("full.png"));
    const std::string bytes = bytes_of(file("full.png"));
    expect_error(raw("half.png", bytes.substr(0, bytes.size() / 2)), "PNG");
}

TEST(PfmFiles, ClampValuesBeyondTheFloatRangeInsteadOfWritingInfinity) {
    // 1e300 is a finite double but an infinite float: the file must hold FLT_MAX.
    const std::filesystem::path path = std::filesystem::temp_directory_path() / "whitted_pfm_clamp.pfm";
    Image image(1, 1, Color(1e300, -1e300, 0.5));
    write_image(image, path);
    const Image back = read_image(path);
    EXPECT_EQ(back.at(0, 0).x, static_cast<double>(std::numeric_limits<float>::max()));
    EXPECT_EQ(back.at(0, 0).y, -static_cast<double>(std::numeric_limits<float>::max()));
    std::filesystem::remove(path);
}

TEST(ImagePictures, BrokenPixelsAreMarkedMagentaAndTheOthersKept) {
    // What `whitted render` writes when a lab's shading gives NaN or infinite colours.
    Image image(3, 1, Color(0.25, 0.5, 0.75));
    image.at(0, 0) = Color(std::numeric_limits<double>::quiet_NaN(), 0.0, 0.0);
    image.at(2, 0) = Color(0.0, std::numeric_limits<double>::infinity(), 0.0);
    const Image shown = with_broken_pixels_marked(image);
    EXPECT_EQ(shown.at(0, 0), Color(1.0, 0.0, 1.0));
    EXPECT_EQ(shown.at(1, 0), Color(0.25, 0.5, 0.75));
    EXPECT_EQ(shown.at(2, 0), Color(1.0, 0.0, 1.0));
    EXPECT_EQ(count_non_finite(image), 2u);
}
