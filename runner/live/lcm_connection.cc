#include "runner/live/lcm_connection.h"

#include <cerrno>
#include <sstream>
#include <vector>

#include "common/error.h"
#include "common/stderr_capture.h"
#include "common/text.h"

namespace areagraph {
namespace {

std::vector<std::string> Split(const std::string& text, char separator) {
  std::vector<std::string> parts;
  std::istringstream in(text);
  std::string part;
  while (std::getline(in, part, separator)) parts.push_back(part);
  return parts;
}

// What the LCM library printed, as " (LCM: ...)" on one line; "" when nothing.
std::string LibraryWords(const std::string& printed) {
  const std::string line = OneLine(printed);
  return line.empty() ? "" : " (LCM: " + line + ")";
}

}  // namespace

std::string MulticastRouteHint() {
  return "udpm needs a multicast route, e.g. as root: 'ip link set lo up; ip route add "
         "224.0.0.0/4 dev lo'; or use --url memq:// within one process";
}

std::string HostLocalLcmUrl(const std::string& url) {
  const size_t separator = url.find("://");
  if (separator == std::string::npos) {
    throw OptionsError("LCM URL '" + url +
                       "' has no provider; expected e.g. udpm://239.255.76.67:7667?ttl=0");
  }
  const std::string provider = url.substr(0, separator);
  if (provider == "memq") return url;
  if (provider != "udpm") {
    throw OptionsError("LCM provider '" + provider + "' in '" + url +
                       "' is not supported; use udpm://ADDRESS:PORT?ttl=0 (this host) or "
                       "memq:// (in process)");
  }
  const size_t query = url.find('?', separator);
  if (query == std::string::npos) return url + "?ttl=0";
  bool has_ttl = false;
  for (const std::string& option : Split(url.substr(query + 1), '&')) {
    if (option.rfind("ttl=", 0) != 0) continue;
    if (option != "ttl=0") {
      throw OptionsError("LCM URL '" + url + "' sets " + option +
                         ", which would send traffic beyond this host; areagraph only uses "
                         "ttl=0");
    }
    has_ttl = true;
  }
  return has_ttl ? url : url + "&ttl=0";
}

std::string ReceivingLcmUrl(const std::string& url) {
  const std::string local_url = HostLocalLcmUrl(url);
  if (local_url.rfind("udpm://", 0) != 0 || local_url.find("recv_buf_size=") != std::string::npos) {
    return local_url;
  }
  // HostLocalLcmUrl always leaves a query (ttl=0) on udpm URLs.
  return local_url + "&recv_buf_size=" + std::to_string(kReceiveBufferBytes);
}

std::unique_ptr<lcm::LCM> OpenLcm(const std::string& url) {
  const std::string local_url = HostLocalLcmUrl(url);
  std::unique_ptr<lcm::LCM> lcm;
  std::string complaint;
  {
    // The LCM library prints its own lines on a failure; they become part
    // of the one line of the error instead.
    ScopedStderrCapture capture;
    lcm = std::make_unique<lcm::LCM>(local_url);
    complaint = capture.Text();
  }
  if (!lcm->good()) {
    std::string message = "cannot open LCM at '" + local_url + "'" + LibraryWords(complaint);
    if (local_url.rfind("udpm://", 0) == 0) {
      message += ": check the multicast address and port; " + MulticastRouteHint();
    }
    throw Error(message);
  }
  return lcm;
}

void StartReceiving(lcm::LCM& lcm, const std::string& url) {
  int fileno = -1;
  std::string complaint;
  {
    ScopedStderrCapture capture;  // udpm opens its receiving socket here
    fileno = lcm.getFileno();
    complaint = capture.Text();
  }
  if (fileno < 0) {
    std::string message = "cannot receive on LCM at '" + url + "'" + LibraryWords(complaint);
    if (url.rfind("udpm://", 0) == 0) message += "; " + MulticastRouteHint();
    throw Error(message);
  }
}

bool HandleOneMessage(lcm::LCM& lcm, int timeout_ms, const std::string& url) {
  errno = 0;
  const int status = lcm.handleTimeout(timeout_ms);
  // A signal (SIGINT, SIGTERM) interrupts the wait: the caller decides.
  if (status < 0 && errno == EINTR) return false;
  if (status < 0) {
    std::string message = "receiving on LCM at '" + url + "' failed";
    if (url.rfind("udpm://", 0) == 0) message += "; " + MulticastRouteHint();
    throw Error(message);
  }
  return status > 0;
}

void AddLcmUrlFlag(CLI::App& app, std::string& url) {
  url = kDefaultLcmUrl;
  app.add_option("--url", url, "LCM URL; udpm must keep ttl=0 (traffic stays on the host)")
      ->capture_default_str();
}

}  // namespace areagraph
