#include "view/view_server.h"

#include <httplib.h>

#include <nlohmann/json.hpp>

#include <chrono>
#include <cstdio>
#include <random>
#include <thread>

#include "io/input_error.h"
#include "view/view_page.h"
#include "view/view_scene_file.h"

namespace tracer {
namespace {

constexpr size_t kMaxRequestBytes = 64 * 1024;  // a camera or an option is a few hundred bytes
constexpr int kWorkers = 4;                     // requests served at once; more wait in the queue

bool same_token(const std::string& given, const std::string& token) {  // in time independent of the first difference
  if (given.size() != token.size()) return false;
  unsigned char diff = 0;
  for (size_t i = 0; i < token.size(); ++i) diff |= static_cast<unsigned char>(given[i] ^ token[i]);
  return diff == 0;
}

void reply_json(httplib::Response& res, int status, const nlohmann::json& body) {
  res.status = status;
  res.set_content(body.dump(), "application/json");
}

void reply_error(httplib::Response& res, int status, const std::string& message) {
  reply_json(res, status, {{"error", message}});
}

nlohmann::json state_json(const ViewFrame& f) {
  return {{"frame", f.id},
          {"width", f.width},
          {"height", f.height},
          {"spp", f.spp},
          {"target_spp", f.target_spp},
          {"preview", f.preview},
          {"pass_seconds", f.pass_seconds},
          {"rays_per_second", f.rays_per_second},
          {"integrator", f.integrator},
          {"camera", camera_block(f.camera)},
          {"error", f.error},
          {"scene_size", f.scene_size}};
}

Json request_body(const httplib::Request& req) {
  try {
    return Json::parse(req.body);
  } catch (const std::exception& e) {
    throw InputError(std::string("request body: not JSON: ") + e.what());
  }
}

}  // namespace

std::string random_token() {
  std::random_device device;  // the system's generator (/dev/urandom)
  char hex[33];
  for (int i = 0; i < 4; ++i) std::snprintf(hex + 8 * i, 9, "%08x", static_cast<unsigned>(device()));
  return std::string(hex, 32);
}

ViewServer::ViewServer(ViewSession& session, const std::string& address, int port)
    : session_(session), address_(address), token_(random_token()), server_(std::make_unique<httplib::Server>()) {
  httplib::Server& s = *server_;
  s.new_task_queue = [] { return new httplib::ThreadPool(kWorkers); };
  s.set_payload_max_length(kMaxRequestBytes);
  s.set_read_timeout(5, 0);
  s.set_write_timeout(5, 0);
  s.set_keep_alive_max_count(100);
  s.set_pre_routing_handler([this](const httplib::Request& req, httplib::Response& res) {
    if (!allowed(req.get_header_value("Host"), req.get_header_value("Origin"))) {
      reply_error(res, 403, "Host or Origin is not this viewer");
      return httplib::Server::HandlerResponse::Handled;
    }
    if (!same_token(req.get_param_value("token"), token_)) {
      reply_error(res, 403, "missing or wrong token: open the URL the viewer printed");
      return httplib::Server::HandlerResponse::Handled;
    }
    res.set_header("Cache-Control", "no-store");
    return httplib::Server::HandlerResponse::Unhandled;
  });
  s.set_exception_handler([](const httplib::Request&, httplib::Response& res, std::exception_ptr error) {
    try {
      std::rethrow_exception(error);
    } catch (const InputError& e) {
      reply_error(res, 400, e.what());
    } catch (const std::exception& e) {
      reply_error(res, 500, e.what());
    } catch (...) {
      reply_error(res, 500, "unknown error");
    }
  });
  s.Get("/", [](const httplib::Request&, httplib::Response& res) { res.set_content(view_page_html(), "text/html"); });
  s.Get("/frame", [this](const httplib::Request&, httplib::Response& res) {
    const ViewFrame f = session_.frame();
    if (!f.png) return reply_error(res, 503, "no frame yet");
    res.set_header("X-Frame", std::to_string(f.id));
    res.set_content(*f.png, "image/png");
  });
  s.Get("/state", [this](const httplib::Request&, httplib::Response& res) {
    reply_json(res, 200, state_json(session_.frame()));
  });
  s.Post("/camera", [this](const httplib::Request& req, httplib::Response& res) {
    const Json body = request_body(req);
    if (!body.is_object() || !body.contains("camera")) throw InputError("request body: expected {\"camera\": {...}}");
    const bool moving = body.contains("moving") && body["moving"].is_boolean() && body["moving"].get<bool>();
    session_.move_camera(read_camera_spec(body["camera"], "request"), moving);
    reply_json(res, 200, {{"camera", camera_block(session_.camera())}});
  });
  s.Post("/settings", [this](const httplib::Request& req, httplib::Response& res) {
    const Json body = request_body(req);
    if (!body.is_object() || body.empty())
      throw InputError("request body: expected {\"integrator\": ..., \"spp\": ...}");
    for (const auto& [name, value] : body.items()) {
      const std::string text = value.is_string() ? value.get<std::string>() : value.dump();
      session_.set_option(name, text);
    }
    reply_json(res, 200, {{"ok", true}});
  });
  s.Post("/save", [this](const httplib::Request&, httplib::Response& res) {
    reply_json(res, 200, {{"files", session_.save()}});
  });
  port_ = port == 0 ? s.bind_to_any_port(address) : (s.bind_to_port(address, port) ? port : -1);
  if (port_ <= 0)
    throw InputError("--bind " + address + " --port " + std::to_string(port) +
                     ": cannot listen there (in use, or not an address of this machine)");
}

ViewServer::~ViewServer() { stop(); }

std::string ViewServer::url() const {
  const std::string host = address_.find(':') != std::string::npos ? "[" + address_ + "]" : address_;
  return "http://" + host + ":" + std::to_string(port_) + "/?token=" + token_;
}

bool ViewServer::allowed(const std::string& host_header, const std::string& origin_header) const {
  const std::string port = ":" + std::to_string(port_);
  // Listening on every address, the machine's names are not known: any Host on this port, and
  // the page's own origin; the token is then what keeps a rebound name out.
  if (address_ == "0.0.0.0" || address_ == "::")
    return host_header.size() > port.size() && host_header.ends_with(port) &&
           (origin_header.empty() || origin_header == "http://" + host_header);
  const std::string names[] = {"127.0.0.1" + port, "localhost" + port, "[::1]" + port,
                               (address_.find(':') != std::string::npos ? "[" + address_ + "]" : address_) + port};
  bool host_ok = false, origin_ok = origin_header.empty();
  for (const std::string& n : names) host_ok |= host_header == n, origin_ok |= origin_header == "http://" + n;
  return host_ok && origin_ok;
}

void ViewServer::serve() {
  serving_ = true;
  if (!stop_requested_) server_->listen_after_bind();
  serving_ = false;
}

// httplib's stop() does nothing before the listening loop has started, so a stop that comes
// first is seen by serve() instead, and one that comes while it starts waits until it can stop it.
void ViewServer::stop() {
  stop_requested_ = true;
  bool stopped = false;
  while (serving_) {
    if (!stopped && server_->is_running()) server_->stop(), stopped = true;
    std::this_thread::sleep_for(std::chrono::milliseconds(5));
  }
}

}  // namespace tracer
