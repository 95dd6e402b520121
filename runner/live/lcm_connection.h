#pragma once

#include <CLI/CLI.hpp>
#include <lcm/lcm-cpp.hpp>
#include <memory>
#include <string>

namespace areagraph {

// The default LCM URL: UDP multicast with ttl=0, so nothing leaves the host.
inline constexpr char kDefaultLcmUrl[] = "udpm://239.255.76.67:7667?ttl=0";

// `url` made safe for areagraph: traffic never leaves this host. A udpm URL
// without ttl gets ttl=0; one with any other ttl is refused. memq:// (in
// process) is local by nature; other providers (tcpq, file) are refused.
// Throws OptionsError saying what to use instead.
std::string HostLocalLcmUrl(const std::string& url);

// Kernel receive buffer that receivers ask for: a grid map arrives as one
// burst of UDP fragments, and with the kernel's usual default (208 KiB) a
// 1400 x 1400 map was lost in tests. The kernel caps the request
// at net.core.rmem_max (LCM warns then); larger maps need that raised.
inline constexpr int kReceiveBufferBytes = 8 << 20;

// HostLocalLcmUrl(url) for a process that receives: udpm URLs without
// recv_buf_size get kReceiveBufferBytes.
std::string ReceivingLcmUrl(const std::string& url);

// An LCM instance on HostLocalLcmUrl(url). Throws Error with the likely fix
// when LCM cannot start (bad address, no multicast route).
std::unique_ptr<lcm::LCM> OpenLcm(const std::string& url);

// Sets up receiving right away rather than at the first wait, so that no
// message sent after this returns is missed (udpm sets up its receive
// socket and thread here). Throws Error with the likely fix.
void StartReceiving(lcm::LCM& lcm, const std::string& url);

// Waits up to `timeout_ms` for one message and dispatches it. Throws Error
// when LCM fails, e.g. when udpm's receive self-test finds no route.
// Returns true when a message was handled, false on timeout or when a
// signal interrupted the wait.
bool HandleOneMessage(lcm::LCM& lcm, int timeout_ms, const std::string& url);

// How to give this host a multicast route on loopback, for error messages.
std::string MulticastRouteHint();

// The LCM URL every executable takes the same way: --url URL, defaulting to
// kDefaultLcmUrl.
void AddLcmUrlFlag(CLI::App& app, std::string& url);

}  // namespace areagraph
