// `tracer view` as a client sees it: the token, Host and Origin checks, 4xx for bad requests, a
// camera move making a new frame, and the saved scene rendering the viewer's image bit for bit.
#include <arpa/inet.h>
#include <gtest/gtest.h>
#include <httplib.h>
#include <netinet/in.h>
#include <sys/socket.h>
#include <unistd.h>

#include <chrono>
#include <cmath>
#include <fstream>
#include <nlohmann/json.hpp>
#include <thread>

#include "image/image_io.h"
#include "render/render_cpu.h"
#include "scene/scene_loader.h"
#include "test_util.h"
#include "view/view_server.h"
#include "view/view_session.h"

namespace tracer {
namespace {

using nlohmann::json;

const char* kScene = R"({
  "format": "tracer-scene/1",
  "camera": {"from": [0, 0.05, 0.2], "to": [0, 0.025, 0], "vfov": 45},
  "film": {"width": 48, "height": 36},
  "render": {"integrator": "path", "spp": 4, "sampler": "sobol", "max_depth": 4},
  "background": {"type": "constant", "radiance": [0.2, 0.2, 0.3]},
  "materials": {"white": {"type": "lambert", "albedo": [0.7, 0.7, 0.7]},
                "lamp": {"type": "emissive", "radiance": [8, 8, 8]}},
  "shapes": [
    {"type": "quad", "material": "white", "corner": [-0.15, 0, 0.15], "u": [0.3, 0, 0], "v": [0, 0, -0.3]},
    {"type": "sphere", "center": [0, 0.025, 0], "radius": 0.025, "material": "white"},
    {"type": "quad", "material": "lamp", "corner": [-0.025, 0.125, -0.025], "u": [0.05, 0, 0], "v": [0, 0, 0.05]}
  ]
})";

class View : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = test::temp_dir("view");
    scene_path_ = (dir_ / "scene.json").string();
    std::ofstream(scene_path_) << kScene;
    ViewOptions options;
    options.scene_path = scene_path_;
    options.scene_text = kScene;
    options.threads = 1;
    options.save_prefix = (dir_ / "scene-view").string();
    session_ = std::make_unique<ViewSession>(options);
    server_ = std::make_unique<ViewServer>(*session_, "127.0.0.1", 0);
    session_->start();
    serving_ = std::thread([this] { server_->serve(); });
    client_ = std::make_unique<httplib::Client>("127.0.0.1", server_->port());
    client_->set_read_timeout(60, 0);
  }
  void TearDown() override {
    server_->stop();
    serving_.join();
    session_->stop();
    std::filesystem::remove_all(dir_);
  }
  std::string with_token(const std::string& path) const { return path + "?token=" + server_->token(); }
  json state() {
    const auto res = client_->Get(with_token("/state").c_str());
    EXPECT_TRUE(res && res->status == 200);
    return res ? json::parse(res->body) : json{};
  }
  // Polls the state until `done` holds (at most 60 s).
  json wait_for(const std::function<bool(const json&)>& done) {
    for (int i = 0; i < 600; ++i) {
      const json s = state();
      if (done(s)) return s;
      std::this_thread::sleep_for(std::chrono::milliseconds(100));
    }
    ADD_FAILURE() << "the viewer did not get there in 60 s: " << state().dump();
    return state();
  }
  int post(const std::string& path, const std::string& body, std::string* reply = nullptr) {
    const auto res = client_->Post(with_token(path).c_str(), body, "application/json");
    if (reply && res) *reply = res->body;
    return res ? res->status : -1;
  }

  std::filesystem::path dir_;
  std::string scene_path_;
  std::unique_ptr<ViewSession> session_;
  std::unique_ptr<ViewServer> server_;
  std::thread serving_;
  std::unique_ptr<httplib::Client> client_;
};

const json kMoved = {{"from", {0.075, 0.06, 0.15}}, {"to", {0.0, 0.02, 0.0}}, {"up", {0, 1, 0}}, {"vfov", 40}};
// Far enough that the scene with the camera grows past half a unit: the ray offset scale, which
// counts the camera's position, doubles from 0.5 to 1 (kernel/geom/ray_offset.h).
const json kFar = {{"from", {0.1, 0.15, 0.5}}, {"to", {0.0, 0.02, 0.0}}, {"up", {0, 1, 0}}, {"vfov", 40}};

TEST_F(View, EveryRequestNeedsTheTokenAndThisServersHostAndOrigin) {
  EXPECT_EQ(client_->Get("/state")->status, 403);
  EXPECT_EQ(client_->Get("/?token=0123")->status, 403);
  EXPECT_EQ(client_->Get(("/?token=" + server_->token() + "x").c_str())->status, 403);
  EXPECT_EQ(client_->Get(with_token("/").c_str())->status, 200);
  const std::string port = std::to_string(server_->port());
  EXPECT_EQ(client_->Get(with_token("/state").c_str(), {{"Host", "attacker.example:" + port}})->status, 403)
      << "a DNS name rebound to 127.0.0.1 is not this viewer";
  EXPECT_EQ(client_->Get(with_token("/state").c_str(), {{"Origin", "http://attacker.example"}})->status, 403);
  EXPECT_EQ(client_->Get(with_token("/state").c_str(), {{"Origin", "http://127.0.0.1:" + port}})->status, 200);
  EXPECT_EQ(client_->Get(with_token("/state").c_str(), {{"Host", "localhost:" + port}})->status, 200);
}

// Listening on every address (--bind 0.0.0.0) the machine's names are unknown: any Host on the
// port passes, an Origin only when it is the Host's own, and the token is still required.
TEST_F(View, OnEveryAddressAnyHostPassesButOnlyItsOwnOriginAndTheToken) {
  ViewServer wide(*session_, "0.0.0.0", 0);
  std::thread serving([&] { wide.serve(); });
  httplib::Client client("127.0.0.1", wide.port());
  const std::string host = "render-box.example:" + std::to_string(wide.port());
  const std::string state = "/state?token=" + wide.token();
  EXPECT_EQ(client.Get(state.c_str(), {{"Host", host}})->status, 200);
  EXPECT_EQ(client.Get(state.c_str(), {{"Host", host}, {"Origin", "http://" + host}})->status, 200);
  EXPECT_EQ(client.Get(state.c_str(), {{"Host", host}, {"Origin", "http://attacker.example"}})->status, 403);
  EXPECT_EQ(client.Get(state.c_str(), {{"Host", "render-box.example:1"}})->status, 403);
  EXPECT_EQ(client.Get("/state", {{"Host", host}})->status, 403);
  wide.stop();
  serving.join();
}

TEST_F(View, BadRequestsGet4xxWithAMessage) {
  std::string reply;
  EXPECT_EQ(post("/camera", "{not json", &reply), 400);
  EXPECT_NE(reply.find("not JSON"), std::string::npos) << reply;
  EXPECT_EQ(post("/camera", R"({"camera": {"from": [0, 1, 4], "vfov": 45}})", &reply), 400);
  EXPECT_NE(reply.find("to"), std::string::npos) << reply;
  EXPECT_EQ(post("/camera", R"({"camera": {"from": [0, 1, 4], "to": [0, 1, 4], "vfov": 45}})"), 400);
  EXPECT_EQ(post("/camera", R"({"camera": {"from": [0, 1, 4], "to": [0, 0, 0], "vfov": 200}})"), 400);
  EXPECT_EQ(post("/camera", R"({"camera": {"from": [0, 1e999, 4], "to": [0, 0, 0], "vfov": 40}})"), 400);
  EXPECT_EQ(post("/settings", R"({"spp": "many"})", &reply), 400);
  EXPECT_NE(reply.find("spp"), std::string::npos) << reply;
  EXPECT_EQ(post("/settings", R"({"integrator": "raymarch"})"), 400);
  EXPECT_EQ(post("/settings", R"({"max_depth": 3})"), 400) << "the viewer sets integrator and spp only";
  EXPECT_EQ(post("/camera", std::string(100000, ' ')), 413);
  EXPECT_EQ(client_->Get(with_token("/scene.json").c_str())->status, 404) << "no request reaches a file";
  EXPECT_EQ(state()["camera"]["from"], json({0.0, 0.05, 0.2})) << "a refused request changed the camera";
}

TEST_F(View, ACameraMoveMakesANewFrameWithThatCamera) {
  const json first = wait_for([](const json& s) { return s["spp"] == 4 && !s["preview"].get<bool>(); });
  // The page's unit of movement: the diagonal of the floor (0.3 x 0.3) and the lamp above it (0.125 up).
  EXPECT_NEAR(first["scene_size"].get<double>(), std::sqrt(0.3 * 0.3 * 2 + 0.125 * 0.125), 1e-5);
  ASSERT_EQ(post("/camera", json{{"camera", kMoved}, {"moving", true}}.dump()), 200);
  const json moving = wait_for([&](const json& s) { return s["frame"] > first["frame"] && s["preview"].get<bool>(); });
  EXPECT_EQ(moving["camera"]["from"], kMoved["from"]);
  EXPECT_EQ(moving["width"], 12) << "a moving camera is drawn at a quarter of the size";
  ASSERT_EQ(post("/camera", json{{"camera", kMoved}, {"moving", false}}.dump()), 200);
  const json rest = wait_for([](const json& s) { return s["spp"] == 4 && !s["preview"].get<bool>(); });
  EXPECT_EQ(rest["camera"]["from"], kMoved["from"]);
  EXPECT_EQ(rest["width"], 48);
  const auto frame = client_->Get(with_token("/frame").c_str());
  ASSERT_TRUE(frame && frame->status == 200);
  EXPECT_EQ(frame->get_header_value("Content-Type"), "image/png");
  const ImagePixels png = read_image_pixels_from_memory(
      std::vector<unsigned char>(frame->body.begin(), frame->body.end()), "png", "frame", 3);
  EXPECT_EQ(png.width, 48u);
  EXPECT_EQ(png.height, 36u);
}

// Item 2 of the viewer's promise: the frame of camera C at N samples is `tracer render`'s image
// of the saved scene (camera C, spp N), bit for bit.
TEST_F(View, TheSavedSceneRendersTheViewersImageBitForBit) {
  ASSERT_EQ(post("/settings", R"({"spp": 3})"), 200);
  ASSERT_EQ(post("/camera", json{{"camera", kFar}, {"moving", false}}.dump()), 200);
  wait_for([](const json& s) {
    return s["spp"] == 3 && s["target_spp"] == 3 && !s["preview"].get<bool>() && s["camera"]["vfov"] == 40.0;
  });
  std::string reply;
  ASSERT_EQ(post("/save", "{}", &reply), 200) << reply;
  const json files = json::parse(reply)["files"];
  ASSERT_EQ(files.size(), 3u);
  const std::string exr = files[0], saved_scene = files[2];
  const Scene scene = load_scene(saved_scene);
  EXPECT_EQ(scene.settings.spp, 3u);
  EXPECT_EQ(scene.offset_scale, 1.0f);
  RenderStats stats;
  const Image rendered = render_cpu(scene, 1, stats);
  const Image viewed = read_image(exr);
  ASSERT_EQ(rendered.rgb.size(), viewed.rgb.size());
  EXPECT_TRUE(rendered.rgb == viewed.rgb) << "the saved scene renders another image than the viewer showed";
  // And a second save never overwrites the first.
  ASSERT_EQ(post("/save", "{}", &reply), 200) << reply;
  EXPECT_NE(json::parse(reply)["files"][0], exr);
}

// The page in headless Chromium: it shows a frame, a drag over it moves the camera through the
// page's own mouse handlers (its #drag-check), and a finished frame shows the moved camera.
TEST_F(View, ThePageInABrowserShowsAFrameAndADragMovesTheCamera) {
  if (test::run_command("command -v chromium") != 0)
    GTEST_SKIP() << "chromium is not installed; ci/install-deps.sh installs it";
  const std::string url =
      "http://127.0.0.1:" + std::to_string(server_->port()) + "/?token=" + server_->token() + "#drag-check";
  // The page polls every 100 ms of the browser's virtual clock, which runs ahead of real time by
  // a factor that varies (from about 2 to about 35 on a 2-core AMD EPYC): a budget of 100 s of it
  // ran out after 1.2 s of real time under the whole suite before the dragged camera's frame was
  // done (and 30 s before that, on a loaded machine). So the budget is 2,000 s of it and the
  // real-time bound is the timeout's 120 s; the page stops polling once checked, and an idle
  // page ends the clock, so a passing check takes no longer.
  std::string dom;
  ASSERT_EQ(test::run_command("timeout 120 chromium --headless --no-sandbox --disable-gpu --user-data-dir=" +
                                  (dir_ / "profile").string() + " --virtual-time-budget=2000000 --dump-dom '" + url +
                                  "' 2>/dev/null",
                              &dom),
            0);
  EXPECT_NE(dom.find("data-frame="), std::string::npos) << "the page never drew a frame:\n" << dom.substr(0, 2000);
  EXPECT_NE(dom.find("data-check=\"camera moved\""), std::string::npos) << "the drag did not move the camera:\n"
                                                                        << dom.substr(0, 2000);
  EXPECT_NE(state()["camera"]["from"], json({0.0, 0.05, 0.2})) << "the server's camera did not move";
}

// Clients that connect and never finish a request (more of them than the server has workers)
// cannot stall the render, and once their read timeout drops them the page is served again.
TEST_F(View, StalledClientsNeitherStallTheRenderNorKeepThePageAway) {
  const uint64_t before = session_->frame().id;
  std::vector<int> sockets;
  for (int i = 0; i < 8; ++i) {
    const int fd = ::socket(AF_INET, SOCK_STREAM, 0);
    sockaddr_in address{};
    address.sin_family = AF_INET;
    address.sin_port = htons(static_cast<uint16_t>(server_->port()));
    address.sin_addr.s_addr = htonl(INADDR_LOOPBACK);
    ASSERT_EQ(::connect(fd, reinterpret_cast<sockaddr*>(&address), sizeof address), 0);
    const char partial[] = "GET /state?token=";
    ASSERT_GT(::send(fd, partial, sizeof partial - 1, 0), 0);
    sockets.push_back(fd);
  }
  session_->set_option("spp", "64");  // work for the render while the clients hang
  std::this_thread::sleep_for(std::chrono::seconds(1));
  EXPECT_GT(session_->frame().id, before) << "the render waited for the clients";
  const json s = wait_for([](const json& st) { return st["target_spp"] == 64; });  // served once they time out
  EXPECT_EQ(s["target_spp"], 64);
  for (const int fd : sockets) ::close(fd);
}

// The command as a user runs it: the URL on stdout, Ctrl-C (SIGINT) ends it with status 0; and
// what it cannot serve is refused with exit 2 naming the file or option, before it listens.
TEST_F(View, TheCommandPrintsItsUrlStopsOnCtrlCAndRefusesBadInput) {
  const std::string tracer = TRACER_BINARY, out = (dir_ / "url.txt").string();
  std::string output;
  EXPECT_EQ(test::run_command("timeout 60 sh -c '" + tracer + " view " + scene_path_ + " --threads 1 > " + out +
                                  " & pid=$!; sleep 2; kill -INT $pid; wait $pid'",
                              &output),
            0)
      << output;
  std::ifstream url_file(out);
  std::string url;
  std::getline(url_file, url);
  EXPECT_EQ(url.rfind("http://127.0.0.1:", 0), 0u) << url;
  EXPECT_NE(url.find("/?token="), std::string::npos) << url;
  EXPECT_EQ(test::run_tracer("view " + (dir_ / "missing.json").string(), &output), 2);
  EXPECT_NE(output.find("missing.json"), std::string::npos) << output;
  EXPECT_EQ(test::run_tracer("view " + scene_path_ + " --port 70000", &output), 2);
  EXPECT_NE(output.find("--port"), std::string::npos) << output;
  EXPECT_EQ(test::run_tracer("view " + scene_path_ + " --save-prefix /nonexistent-dir/x", &output), 2);
  EXPECT_NE(output.find("--save-prefix"), std::string::npos) << output;
  EXPECT_EQ(test::run_tracer("view " + scene_path_ + " --noise-threshold 0.1", &output), 2);
  EXPECT_NE(output.find("noise_threshold"), std::string::npos) << output;
  EXPECT_EQ(test::run_tracer("view " + scene_path_ + " --samples 0:2", &output), 2);
  EXPECT_NE(output.find("--samples"), std::string::npos) << output;
}

}  // namespace
}  // namespace tracer
