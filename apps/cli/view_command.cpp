// SPDX-License-Identifier: MIT
#include "apps/cli/view_command.hpp"

#include <httplib.h>
#include <sys/socket.h>

#include <array>
#include <cerrno>
#include <cstdint>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <iterator>
#include <memory>
#include <nlohmann/json.hpp>
#include <optional>
#include <sstream>
#include <string>

#include "apps/cli/viewer_bundle.hpp"

namespace sparsedyn::cli {
namespace {

struct ViewOptions {
  std::string recording_file;
  int port = 8765;
  std::string html_file;
};

// docs/recording-format.md "Layout": magic, u32 version, u32 header_bytes, header JSON.
constexpr std::array<unsigned char, 8> kMagic = {'S', 'D', 'R', 'E', 'C', '\r', '\n', 0x1a};
constexpr std::uint32_t kVersion = 1;
constexpr std::size_t kPreambleBytes = 16;

std::uint32_t LittleEndianU32(const std::string& bytes, std::size_t at) {
  std::uint32_t value = 0;
  for (int k = 3; k >= 0; --k) {
    value = (value << 8) | static_cast<unsigned char>(bytes[at + static_cast<std::size_t>(k)]);
  }
  return value;
}

// Checks that `bytes` start like a recording this viewer reads; the page parses the rest (and
// reports a truncated or damaged record stream itself). Returns an error message or nothing.
std::optional<std::string> CheckRecording(const std::string& bytes) {
  if (bytes.size() < kPreambleBytes || std::memcmp(bytes.data(), kMagic.data(), kMagic.size())) {
    return "not a sparsedyn recording (the file does not start with the .sdrec magic bytes)";
  }
  const std::uint32_t version = LittleEndianU32(bytes, 8);
  if (version != kVersion) {
    return "recording version " + std::to_string(version) +
           " is not supported (the viewer "
           "reads version " +
           std::to_string(kVersion) + ")";
  }
  const std::uint32_t header_bytes = LittleEndianU32(bytes, 12);
  if (header_bytes > bytes.size() - kPreambleBytes) {
    return "truncated recording: the header needs " + std::to_string(header_bytes) + " bytes";
  }
  const nlohmann::json header = nlohmann::json::parse(
      bytes.begin() + kPreambleBytes, bytes.begin() + kPreambleBytes + header_bytes, nullptr,
      /*allow_exceptions=*/false);
  if (!header.is_object() || !header.contains("bodies") || !header.contains("shapes")) {
    return "the recording's header is not a JSON object with 'bodies' and 'shapes'";
  }
  return std::nullopt;
}

std::optional<std::string> ReadFile(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) return std::nullopt;
  return std::string(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
}

std::string Base64(const std::string& bytes) {
  static constexpr char kDigits[] =
      "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
  std::string out;
  out.reserve((bytes.size() + 2) / 3 * 4);
  for (std::size_t i = 0; i < bytes.size(); i += 3) {
    // 3 bytes -> 24 bits -> 4 digits; '=' pads a short last group.
    std::uint32_t group = static_cast<unsigned char>(bytes[i]) << 16;
    if (i + 1 < bytes.size()) group |= static_cast<unsigned char>(bytes[i + 1]) << 8;
    if (i + 2 < bytes.size()) group |= static_cast<unsigned char>(bytes[i + 2]);
    out += kDigits[(group >> 18) & 63];
    out += kDigits[(group >> 12) & 63];
    out += i + 1 < bytes.size() ? kDigits[(group >> 6) & 63] : '=';
    out += i + 2 < bytes.size() ? kDigits[group & 63] : '=';
  }
  return out;
}

std::string HtmlEscape(const std::string& text) {
  std::string out;
  for (char c : text) {
    switch (c) {
      case '&':
        out += "&amp;";
        break;
      case '<':
        out += "&lt;";
        break;
      case '>':
        out += "&gt;";
        break;
      case '"':
        out += "&quot;";
        break;
      default:
        out += c;
    }
  }
  return out;
}

void ReplaceOnce(std::string& text, const std::string& what, const std::string& with) {
  const std::size_t at = text.find(what);
  if (at != std::string::npos) text.replace(at, what.size(), with);
}

// The served page with the script inlined and the recording embedded as base64 (what the page
// looks for first, viewer/src/main.js RecordingBytes).
std::string SelfContainedPage(const ViewerBundle& bundle, const std::string& recording,
                              const std::string& name) {
  std::string js = bundle.js;
  // "</script" inside the script would end the element early; "<\/script" means the same in JS.
  for (std::size_t at = js.find("</script"); at != std::string::npos;
       at = js.find("</script", at)) {
    js.replace(at, 2, "<\\/");
  }
  std::string page = bundle.html;
  ReplaceOnce(page, "<script src=\"viewer.js\"></script>", "<script>\n" + js + "\n</script>");
  ReplaceOnce(page, "<!-- sparsedyn:recording -->",
              "<script id=\"sdrec-data\" type=\"application/octet-stream\" data-name=\"" +
                  HtmlEscape(name) + "\">\n" + Base64(recording) + "\n</script>");
  return page;
}

int WriteHtml(const ViewOptions& options, const ViewerBundle& bundle, const std::string& bytes) {
  const std::string name = std::filesystem::path(options.recording_file).filename().string();
  const std::string page = SelfContainedPage(bundle, bytes, name);
  std::ofstream out(options.html_file, std::ios::binary);
  if (!out || !out.write(page.data(), static_cast<std::streamsize>(page.size())) || !out.flush()) {
    std::cerr << "sparsedyn view: cannot write " << options.html_file << "\n";
    return 1;
  }
  std::cout << "sparsedyn view: wrote " << options.html_file << " (" << page.size()
            << " bytes); open it in a web browser\n";
  return 0;
}

int Serve(const ViewOptions& options, const ViewerBundle& bundle, const std::string& bytes) {
  httplib::Server server;
  // httplib's default sets SO_REUSEPORT, which would let two servers share a port silently;
  // SO_REUSEADDR alone still restarts at once on a port left in TIME_WAIT.
  server.set_socket_options([](socket_t sock) {
    int yes = 1;
    setsockopt(sock, SOL_SOCKET, SO_REUSEADDR, &yes, sizeof(yes));
  });
  auto page = [&bundle](const httplib::Request&, httplib::Response& response) {
    response.set_content(bundle.html, "text/html; charset=utf-8");
  };
  server.Get("/", page);
  server.Get("/viewer.html", page);
  server.Get("/viewer.js", [&bundle](const httplib::Request&, httplib::Response& response) {
    response.set_content(bundle.js, "text/javascript; charset=utf-8");
  });
  server.Get("/recording.sdrec", [&bytes](const httplib::Request&, httplib::Response& response) {
    response.set_header("Cache-Control", "no-store");
    response.set_content(bytes, "application/octet-stream");
  });
  const std::string host = "127.0.0.1";
  int port = options.port;
  if (port == 0) {
    port = server.bind_to_any_port(host);
  } else if (!server.bind_to_port(host, port)) {
    port = -1;
  }
  if (port <= 0) {
    std::cerr << "sparsedyn view: cannot listen on " << host << ":" << options.port
              << " (is the port in use? choose another with --port, or --port 0 for any)\n";
    return 1;
  }
  std::cout << "sparsedyn view: serving " << options.recording_file << " at http://" << host << ":"
            << port << "/  (Ctrl-C stops)" << std::endl;
  return server.listen_after_bind() ? 0 : 1;
}

int View(const ViewOptions& options) {
  const std::optional<std::string> bytes = ReadFile(options.recording_file);
  if (!bytes) {
    std::cerr << "sparsedyn view: cannot read " << options.recording_file << ": "
              << std::strerror(errno) << "\n";
    return 1;
  }
  if (std::optional<std::string> error = CheckRecording(*bytes)) {
    std::cerr << "sparsedyn view: " << options.recording_file << ": " << *error << "\n";
    return 1;
  }
  const ViewerBundle bundle = EmbeddedViewer();
  if (bundle.html.empty() || bundle.js.empty()) {
    std::cerr << "sparsedyn view: this sparsedyn was built without the web viewer: node and npm "
                 "were not found when it was configured (install them, e.g. with "
                 "scripts/deps.sh, then configure and build again)\n";
    return 1;
  }
  if (!options.html_file.empty()) return WriteHtml(options, bundle, *bytes);
  return Serve(options, bundle, *bytes);
}

}  // namespace

void AddViewCommand(CLI::App& app) {
  auto options = std::make_shared<ViewOptions>();
  CLI::App* view = app.add_subcommand(
      "view", "Play a recording in the web viewer (served on localhost, or one HTML file)");
  view->add_option("recording", options->recording_file, "Recording (.sdrec)")->required();
  view->add_option("--port", options->port, "Port on 127.0.0.1 (0: any free port)")
      ->check(CLI::Range(0, 65535));
  view->add_option("--html", options->html_file,
                   "Write one self-contained HTML file (viewer + recording) instead of serving");
  view->callback([options] { throw CLI::RuntimeError(View(*options)); });
}

}  // namespace sparsedyn::cli
