// SPDX-License-Identifier: Apache-2.0
// LUT inputs that are not what they seem (issue 17): special files given as a LUT, a .cube that
// changes while it is read, headers that claim far more than the file holds, and allocations that
// fail. Each case ends in one line naming the file, never a hang, a signal or a raw
// std::bad_alloc, and memory follows what the file holds.
#include "RobustSupport.h"
#include "TestPaths.h"

#include "lut/Error.h"
#include "lut/Limits.h"
#include "lut/formats/Registry.h"

#include <OpenImageIO/imageio.h>
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <fcntl.h>
#include <filesystem>
#include <new>
#include <sys/socket.h>
#include <sys/stat.h>
#include <sys/un.h>
#include <sys/wait.h>
#include <thread>
#include <unistd.h>

namespace fs = std::filesystem;
using namespace lut::robust;
using ::testing::HasSubstr;
using ::testing::Not;

// Every operator new of this test binary goes through here, so a test can see the largest size
// asked for while it reads a file, and make any one allocation over a cap fail with
// std::bad_alloc as if memory had run out (deterministic, unlike an address-space limit). The
// replacements pair malloc with free, which GCC cannot see through.
#if defined(__GNUC__) && !defined(__clang__)
#pragma GCC diagnostic ignored "-Wmismatched-new-delete"
#endif
namespace {
std::atomic<std::size_t> g_capBytes{0}; // 0 = no cap
std::atomic<std::size_t> g_largest{0};
} // namespace

void* operator new(std::size_t n) {
    std::size_t seen = g_largest.load(std::memory_order_relaxed);
    while (n > seen && !g_largest.compare_exchange_weak(seen, n, std::memory_order_relaxed)) {
    }
    const std::size_t cap = g_capBytes.load(std::memory_order_relaxed);
    if (cap != 0 && n > cap)
        throw std::bad_alloc();
    if (void* p = std::malloc(n ? n : 1))
        return p;
    throw std::bad_alloc();
}
void* operator new[](std::size_t n) {
    return operator new(n);
}
void operator delete(void* p) noexcept {
    std::free(p);
}
void operator delete[](void* p) noexcept {
    std::free(p);
}
void operator delete(void* p, std::size_t) noexcept {
    std::free(p);
}
void operator delete[](void* p, std::size_t) noexcept {
    std::free(p);
}

namespace {

// Records the largest allocation from now on, and caps one allocation at capBytes (0 = no cap)
// until destroyed.
class AllocationProbe {
public:
    explicit AllocationProbe(std::size_t capBytes = 0) {
        g_largest = 0;
        g_capBytes = capBytes;
    }
    ~AllocationProbe() { g_capBytes = 0; }
    std::size_t largest() const { return g_largest.load(); }
};

using lut::test::shellQuoted;

// Runs the CLI killed after `seconds` (exit 137): a reader that blocks fails the test instead of
// hanging the suite.
lut::test::RunResult runCliBounded(const std::string& args, int seconds = 30) {
    const fs::path dir = fs::path(LUTKIT_BINARY_DIR) / "test-tmp" / "cli-capture";
    fs::create_directories(dir);
    static int counter = 0;
    const std::string tag = std::to_string(::getpid()) + "_b" + std::to_string(counter++);
    const fs::path out = dir / ("out_" + tag), err = dir / ("err_" + tag);
    const std::string cmd =
        "timeout -s KILL " + std::to_string(seconds) + " " + shellQuoted(LUTKIT_CLI) + " " + args +
        " >" + shellQuoted(out.string()) + " 2>" + shellQuoted(err.string()) + " </dev/null";
    const int status = std::system(cmd.c_str());
    lut::test::RunResult r;
    r.exitCode = WIFEXITED(status) ? WEXITSTATUS(status) : 128 + WTERMSIG(status);
    r.out = fileBytes(out.string());
    r.err = fileBytes(err.string());
    fs::remove(out);
    fs::remove(err);
    return r;
}

void writePng(const std::string& path, int w, int h) {
    auto out = OIIO::ImageOutput::create(path);
    ASSERT_TRUE(out);
    std::vector<float> px(static_cast<std::size_t>(w) * h * 3, 0.5f);
    ASSERT_TRUE(out->open(path, OIIO::ImageSpec(w, h, 3, OIIO::TypeDesc::UINT8)));
    ASSERT_TRUE(out->write_image(OIIO::TypeDesc::FLOAT, px.data()));
    out->close();
}

// Problem 3: a FIFO given as a LUT made info, validate, convert and apply --lut wait forever
// (the file was opened before its type was checked). Sockets, directories and devices are
// refused the same way, each named for what it is.
TEST(SpecialFiles, FifoSocketDirectoryAndDeviceAsALutAreRefusedWithoutBlocking) {
    const std::string dir = lut::test::tempDir();
    writePng(dir + "/img.png", 8, 8);
    struct Special {
        std::string name;
        std::string kind;
    };
    std::vector<Special> specials;
    for (const char* ext : {".cube", ".nutexb", ".png", ".3dl"}) {
        const std::string name = std::string("fifo") + ext;
        ASSERT_EQ(::mkfifo((dir + "/" + name).c_str(), 0644), 0);
        specials.push_back({name, "a FIFO"});
    }
    fs::create_directory(dir + "/folder.cube");
    specials.push_back({"folder.cube", "a directory"});
    fs::create_symlink("/dev/zero", dir + "/zero.nutexb");
    specials.push_back({"zero.nutexb", "a character device"});
    const std::string sock = dir + "/sock.cube";
    const int fd = ::socket(AF_UNIX, SOCK_STREAM, 0);
    sockaddr_un addr{};
    addr.sun_family = AF_UNIX;
    if (fd >= 0 && sock.size() < sizeof addr.sun_path) {
        std::memcpy(addr.sun_path, sock.c_str(), sock.size() + 1);
        if (::bind(fd, reinterpret_cast<sockaddr*>(&addr), sizeof addr) == 0)
            specials.push_back({"sock.cube", "a socket"});
    }

    for (const auto& s : specials) {
        const std::string path = dir + "/" + s.name;
        const std::string expected = path + ": is " + s.kind + ", not a regular file";
        for (const std::string& args :
             {"info " + shellQuoted(path), "validate " + shellQuoted(path),
              "convert " + shellQuoted(path) + " " + shellQuoted(dir + "/o.cube"),
              "apply --lut " + shellQuoted(path) + " " + shellQuoted(dir + "/img.png") + " -o " +
                  shellQuoted(dir + "/o.png")}) {
            SCOPED_TRACE(args);
            const auto r = runCliBounded(args);
            EXPECT_EQ(r.exitCode, 1);
            EXPECT_THAT(r.err, HasSubstr(expected));
            EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
        }
        // The library says the same (no CLI in between).
        try {
            (void)lut::formats::readLut(path);
            ADD_FAILURE() << s.name << " accepted";
        } catch (const lut::Error& e) {
            EXPECT_EQ(std::string(e.what()), expected);
        }
    }
    if (fd >= 0)
        ::close(fd);
    EXPECT_FALSE(fs::exists(dir + "/o.cube"));
    EXPECT_FALSE(fs::exists(dir + "/o.png"));
}

// Problem 4: the .cube reader mapped the file, so a LUT rewritten in place by another program
// while lutkit read it killed lutkit with SIGBUS. Now the file is read into memory and its size
// and time are compared before and after: every read gives the table, a clean error for what it
// saw, or "changed while being read" -- never a signal.
TEST(ChangingFiles, CubeThatShrinksAndGrowsWhileReadIsReportedNeverASignal) {
    const std::string dir = lut::test::tempDir();
    const std::string path = dir + "/moving.cube";
    const std::string full = neutralCube(48); // 110592 rows, ~2.8 MB: read on all cores
    writeBytes(path, full);
    std::atomic<bool> stop{false};
    std::thread writer([&] {
        const int fd = ::open(path.c_str(), O_WRONLY);
        ASSERT_GE(fd, 0);
        const std::size_t half = full.size() / 2;
        while (!stop) {
            // Shrink to half, then grow back: what a program rewriting the LUT in place does.
            (void)!::ftruncate(fd, static_cast<off_t>(half));
            (void)!::pwrite(fd, full.data() + half, full.size() - half, static_cast<off_t>(half));
        }
        ::close(fd);
    });
    int changed = 0, read = 0, other = 0;
    const auto start = std::chrono::steady_clock::now();
    for (int i = 0; i < 400 && (changed == 0 || i < 40); ++i) {
        if (std::chrono::steady_clock::now() - start > std::chrono::seconds(20))
            break;
        try {
            const lut::LutFile f = lut::formats::readLut(path);
            EXPECT_EQ(f.cube->size(), 48);
            ++read;
        } catch (const lut::Error& e) {
            const std::string m = e.what();
            EXPECT_THAT(m, HasSubstr("moving.cube"));
            EXPECT_EQ(m.find('\n'), std::string::npos);
            if (m.rfind(path + ": the file changed while being read (", 0) == 0)
                ++changed;
            else
                ++other; // a consistent snapshot of a half-written file: refused as malformed
        }
    }
    stop = true;
    writer.join();
    RecordProperty("reads", read);
    RecordProperty("changed", changed);
    RecordProperty("malformed", other);
    EXPECT_GT(changed, 0) << read << " reads, " << other << " other errors";
}

std::string readLutMessage(const std::string& path) {
    try {
        (void)lut::formats::readLut(path);
    } catch (const lut::Error& e) {
        return e.what();
    }
    return "(accepted)";
}

// Memory bounded by what the file holds: a 22-byte .cube declaring LUT_3D_SIZE 256 with one row
// allocated (and zeroed) the 201 MB table before reporting the missing rows. Now the declared
// rows are checked against the bytes after the header (each row takes at least 6) first; the
// message is the same as ever.
TEST(HostileSizes, TinyCubeDeclaring256CubedAllocatesNothingBig) {
    const std::string dir = lut::test::tempDir();
    writeBytes(dir + "/tiny.cube", "LUT_3D_SIZE 256\n0 0 0\n");
    ASSERT_EQ(fs::file_size(dir + "/tiny.cube"), 22u);
    AllocationProbe probe;
    EXPECT_EQ(stripDir(readLutMessage(dir + "/tiny.cube"), dir),
              "tiny.cube:3:1: expected 16777216 data rows for LUT_3D_SIZE 256, found 1 before the "
              "end of the file");
    EXPECT_LT(probe.largest(), 1u << 20); // the table alone would be 201326592 bytes
    // Shaper + cube: the same check counts both tables' rows.
    writeBytes(dir + "/both.cube", "LUT_1D_SIZE 65536\nLUT_3D_SIZE 256\n0 0 0\n0 0 0\n");
    EXPECT_EQ(stripDir(readLutMessage(dir + "/both.cube"), dir),
              "both.cube:5:1: expected 65536 + 16777216 = 16842752 data rows for LUT_1D_SIZE "
              "65536 and LUT_3D_SIZE 256, found 2 before the end of the file");
    EXPECT_LT(probe.largest(), 1u << 20);
    // A file that does hold its rows still reads (the check counts bytes, not just lines).
    writeBytes(dir + "/short-rows.cube", "LUT_3D_SIZE 2\n0 0 0\n1 0 0\n0 1 0\n1 1 0\n0 0 1\n"
                                         "1 0 1\n0 1 1\n1 1 1");
    EXPECT_EQ(readLutMessage(dir + "/short-rows.cube"), "(accepted)");
}

// A LUT image's picture size comes from its header; a size no layout has is refused before the
// pixels are decoded. A 16384x16384 RGBA PNG (within the image pixel limit, 60 bytes) was decoded
// into gigabytes of floats first. In 60 bytes it is refused by the image rule (its IDAT cannot
// hold that many pixels: issue 29); with 1.1 MB of IDAT, which could, by the layouts' sizes.
TEST(HostileSizes, LutImageHeaderClaimingAHugePictureIsRefusedBeforeDecoding) {
    const std::string dir = lut::test::tempDir();
    auto png = [](const std::string& data) { return craftedPng(16384, 16384, 6, data); };
    writeBytes(dir + "/huge.png", png("\x78\x01"));
    writeBytes(dir + "/big.png", png("\x78\x01" + std::string(1100000, '\0')));
    AllocationProbe probe(256u << 20); // an allocation of gigabytes fails instead of swapping
    EXPECT_EQ(stripDir(readLutMessage(dir + "/huge.png"), dir),
              "huge.png: declares 16384x16384 pixels (1073758208 bytes as stored) in 2 bytes of "
              "PNG data, more than deflate data can hold (at most 1032:1): truncated or corrupt");
    EXPECT_EQ(stripDir(readLutMessage(dir + "/big.png"), dir),
              "big.png: image is 16384x16384, not a LUT image size: unreal, unity and smush need "
              "N^2 x N (e.g. 256x16), hald needs L^3 x L^3 (e.g. 64x64)");
    EXPECT_LT(probe.largest(), 64u << 20);
}

// std::bad_alloc while reading a LUT escaped as a raw "std::bad_alloc". Now it is one line naming
// the file and the size asked for. Memory "runs out" for any one allocation over 20 MiB: the file
// and its untiled copy fit, the 24 MiB table does not.
TEST(HostileSizes, OutOfMemoryNamesTheFileAndTheSizeAskedFor) {
    const std::string dir = lut::test::tempDir();
    // A 128^3 .cube of the shortest rows: 12.6 MB of text, a 24 MiB table.
    {
        std::string text = "LUT_3D_SIZE 128\n";
        text.reserve(16 + 6 * 128 * 128 * 128);
        for (int i = 0; i < 128 * 128 * 128; ++i)
            text += "0 0 0\n";
        writeBytes(dir + "/big.cube", text);
    }
    // A 128^3 block-linear nutexb: 8 MiB of data, an 8 MiB untiled copy, a 24 MiB table.
    NutexbFields f;
    f.width = f.height = f.depth = 128;
    f.dataSize = 8u << 20;
    writeBytes(dir + "/big.nutexb", nutexbFile(f, 8u << 20));
    {
        AllocationProbe probe(20u << 20);
        EXPECT_EQ(stripDir(readLutMessage(dir + "/big.cube"), dir),
                  "big.cube: out of memory: the LUT_3D_SIZE 128 table needs 25165824 bytes "
                  "(24.0 MiB)");
        EXPECT_EQ(stripDir(readLutMessage(dir + "/big.nutexb"), dir),
                  "big.nutexb: out of memory: the 128^3 table needs 25165824 bytes (24.0 MiB)");
    }
    // With memory to spare both read.
    EXPECT_EQ(readLutMessage(dir + "/big.cube"), "(accepted)");
    EXPECT_EQ(readLutMessage(dir + "/big.nutexb"), "(accepted)");
}

} // namespace
