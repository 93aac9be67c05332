// `tracer view`'s HTTP side (cpp-httplib): the page, its frames and its requests. Every request
// must carry the session's random token (?token=) and name this server in its Host header,
// and in its Origin header when it has one (a page of another site, or a DNS name rebound to
// this address, is refused); no request names a file. Bad requests get 4xx with a message.
#pragma once
#include <atomic>
#include <memory>
#include <string>

#include "view/view_session.h"

namespace httplib {
class Server;
}

namespace tracer {

class ViewServer {
 public:
  // Binds `address` on `port` (0: a free port of the system's choosing); InputError when it cannot.
  ViewServer(ViewSession& session, const std::string& address, int port);
  ~ViewServer();
  int port() const { return port_; }
  const std::string& token() const { return token_; }
  std::string url() const;  // http://ADDRESS:PORT/?token=TOKEN
  void serve();             // until stop(); from one thread
  void stop();              // from any thread, before, during or after serve()

 private:
  bool allowed(const std::string& host_header, const std::string& origin_header) const;

  ViewSession& session_;
  std::string address_, token_;
  int port_ = 0;
  std::unique_ptr<httplib::Server> server_;
  std::atomic<bool> serving_{false}, stop_requested_{false};
};

// 128 random bits from the system's generator, as 32 hex digits.
std::string random_token();

}  // namespace tracer
