// SPDX-License-Identifier: MIT
// `sparsedyn view`: bad inputs fail with a message and a non-zero status; --html writes one
// page that holds the viewer and the recording. (The page itself is tested in headless
// Chromium: tests/viewer/browser_test.js.)
#include <arpa/inet.h>
#include <gtest/gtest.h>
#include <netinet/in.h>
#include <sys/socket.h>
#include <unistd.h>

#include <array>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>

namespace {

struct Output {
  int status;
  std::string out;
};

// Runs the CLI with `arguments`, stdout and stderr together; a server that wrongly starts is
// stopped by timeout(1) after 20 s (status 124).
Output RunCli(const std::string& arguments) {
  const std::string command =
      "timeout 20 " + std::string(SPARSEDYN_CLI_PATH) + " " + arguments + " 2>&1";
  FILE* pipe = popen(command.c_str(), "r");
  std::string out;
  std::array<char, 4096> buffer{};
  while (std::fgets(buffer.data(), buffer.size(), pipe) != nullptr) out += buffer.data();
  const int status = pclose(pipe);
  return {WEXITSTATUS(status), out};
}

std::filesystem::path TempPath(const std::string& name) {
  return std::filesystem::temp_directory_path() /
         ("sparsedyn_view_test_" + std::to_string(getpid()) + "_" + name);
}

void WriteBytes(const std::filesystem::path& path, const std::string& bytes) {
  std::ofstream(path, std::ios::binary) << bytes;
}

// The smallest valid recording (docs/recording-format.md): one sphere body, one segment, end.
std::string TinyRecording() {
  std::string bytes("SDREC\r\n\x1a", 8);
  auto u32 = [&bytes](std::uint32_t v) {
    for (int k = 0; k < 4; ++k) bytes += static_cast<char>((v >> (8 * k)) & 0xff);
  };
  auto f64 = [&bytes](double v) {
    char raw[8];
    std::memcpy(raw, &v, 8);
    bytes.append(raw, 8);
  };
  const std::string header =
      R"({"bodies":1,"shapes":[{"type":"sphere","radius":0.5}],"start_time":0,"end_time":1})";
  u32(1);
  u32(static_cast<std::uint32_t>(header.size()));
  bytes += header;
  u32(0);  // body: shape, flags, mass, bounding radius
  u32(0);
  f64(1.0);
  f64(0.5);
  bytes += '\x01';  // segment: tag, flags, body, t0, position, velocity
  bytes += '\x00';
  u32(0);
  for (double v : {0.0, 0.0, 0.0, 0.0, 1.0, 0.0, 0.0}) f64(v);
  bytes += '\x03';  // end
  f64(1.0);
  return bytes;
}

bool BuiltWithViewer() {
  const std::filesystem::path rec = TempPath("probe.sdrec");
  WriteBytes(rec, TinyRecording());
  const Output probe = RunCli("view " + rec.string() + " --html /dev/null");
  std::filesystem::remove(rec);
  return probe.out.find("built without the web viewer") == std::string::npos;
}

// Configured without node/npm there is no bundle to test (and in CI tests/viewer registers a
// failing viewer.tools_missing instead); configured with them, a missing bundle is a failure.
#define SPARSEDYN_REQUIRE_VIEWER()                                            \
  do {                                                                        \
    if (!SPARSEDYN_HAS_VIEWER) GTEST_SKIP() << "configured without node/npm"; \
    ASSERT_TRUE(BuiltWithViewer()) << "node/npm were found, yet no bundle";   \
  } while (false)

TEST(CliView, MissingFileFailsNamingIt) {
  const Output result = RunCli("view /nonexistent/run.sdrec --html out.html");
  EXPECT_NE(result.status, 0);
  EXPECT_NE(result.out.find("/nonexistent/run.sdrec"), std::string::npos) << result.out;
}

TEST(CliView, FileThatIsNotARecordingFails) {
  const std::filesystem::path path = TempPath("not_a_recording.sdrec");
  WriteBytes(path, "{\"this\": \"is json\"}\n");
  const Output result = RunCli("view " + path.string() + " --html /dev/null");
  EXPECT_NE(result.status, 0);
  EXPECT_NE(result.out.find("not a sparsedyn recording"), std::string::npos) << result.out;
  std::filesystem::remove(path);
}

TEST(CliView, UnknownVersionFailsNamingBothVersions) {
  std::string bytes = TinyRecording();
  bytes[8] = 7;
  const std::filesystem::path path = TempPath("v7.sdrec");
  WriteBytes(path, bytes);
  const Output result = RunCli("view " + path.string() + " --html /dev/null");
  EXPECT_NE(result.status, 0);
  EXPECT_NE(result.out.find("version 7"), std::string::npos) << result.out;
  EXPECT_NE(result.out.find("version 1"), std::string::npos) << result.out;
  std::filesystem::remove(path);
}

TEST(CliView, HtmlHoldsTheViewerAndTheRecording) {
  SPARSEDYN_REQUIRE_VIEWER();
  const std::filesystem::path rec = TempPath("tiny.sdrec");
  const std::filesystem::path html = TempPath("tiny.html");
  WriteBytes(rec, TinyRecording());
  const Output result = RunCli("view " + rec.string() + " --html " + html.string());
  ASSERT_EQ(result.status, 0) << result.out;
  std::ifstream in(html, std::ios::binary);
  const std::string page{std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
  EXPECT_NE(page.find("id=\"sdrec-data\""), std::string::npos);
  EXPECT_NE(page.find("U0RSRUMNChoB"), std::string::npos);  // base64 of magic + version 1
  EXPECT_EQ(page.find("<script src="), std::string::npos);  // nothing left to fetch
  std::filesystem::remove(rec);
  std::filesystem::remove(html);
}

TEST(CliView, PortInUseFailsWithAMessage) {
  SPARSEDYN_REQUIRE_VIEWER();
  // Hold a port on 127.0.0.1, then ask `view` for the same one.
  const int holder = socket(AF_INET, SOCK_STREAM, 0);
  ASSERT_GE(holder, 0);
  sockaddr_in address{};
  address.sin_family = AF_INET;
  address.sin_addr.s_addr = htonl(INADDR_LOOPBACK);
  address.sin_port = 0;
  ASSERT_EQ(bind(holder, reinterpret_cast<sockaddr*>(&address), sizeof(address)), 0);
  ASSERT_EQ(listen(holder, 1), 0);
  socklen_t length = sizeof(address);
  ASSERT_EQ(getsockname(holder, reinterpret_cast<sockaddr*>(&address), &length), 0);
  const int port = ntohs(address.sin_port);

  const std::filesystem::path rec = TempPath("port.sdrec");
  WriteBytes(rec, TinyRecording());
  const Output result = RunCli("view " + rec.string() + " --port " + std::to_string(port));
  close(holder);
  EXPECT_NE(result.status, 0);
  EXPECT_NE(result.out.find("cannot listen on 127.0.0.1:" + std::to_string(port)),
            std::string::npos)
      << result.out;
  std::filesystem::remove(rec);
}

}  // namespace
