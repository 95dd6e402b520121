#pragma once

#include <string>

namespace areagraph::testing {

// Debian's chromium, headless, for the viewer's browser tests. Every run gets
// a fresh profile and the flags that keep chromium from calling home
// (background networking, component updates, sync, QUIC), and runs inside
// `unshare -n` (no network at all) where the system allows it.
class HeadlessChromium {
 public:
  // Why chromium is missing ("" when it is installed). Cheap: for SetUp.
  static const std::string& NotInstalled();

  // Why chromium cannot start on this machine ("" when it can): not
  // installed, or it fails to print the DOM of a blank page. Costs a browser
  // start, so tests ask only after a page failed to load.
  static const std::string& Unavailable();

  // Whether runs happen inside a network namespace without any network.
  static bool Offline();

  struct PageLoad {
    int exit_code = -1;
    std::string dom;      // --dump-dom after the load event
    std::string console;  // the page's console messages (chromium's log lines)
  };

  // Loads `url` and dumps the DOM after the load event, or with `settle_ms`
  // once the page has been idle or that much virtual time has passed (for
  // work the page does after loading, such as decoding images).
  static PageLoad DumpDom(const std::string& url, int settle_ms = 0);

  // Loads `url` in a window of width x height and writes a PNG screenshot.
  // Returns false when chromium fails or writes no file.
  static bool Screenshot(const std::string& url, const std::string& png_path, int width,
                         int height);
};

// The file:// URL of a local path.
std::string FileUrl(const std::string& path);

}  // namespace areagraph::testing
