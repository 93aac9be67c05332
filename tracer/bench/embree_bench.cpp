#include "bench/embree_bench.h"

#include <embree3/rtcore.h>
#include <omp.h>

#include <atomic>
#include <chrono>
#include <string>

#include "io/input_error.h"

namespace tracer {
namespace {

std::atomic<long long> g_bytes{0}, g_peak{0};

bool monitor(void*, ssize_t bytes, bool) {
  const long long now = g_bytes += bytes;
  long long peak = g_peak.load();
  while (now > peak && !g_peak.compare_exchange_weak(peak, now)) {
  }
  return true;
}

double mrays(size_t n, std::chrono::steady_clock::time_point start) {
  return static_cast<double>(n) / std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count() / 1e6;
}

// Our ray as Embree's, over (0, tfar].
RTCRay to_rtc(const Ray& r, float tfar) {
  RTCRay ray{};
  ray.org_x = r.origin.x, ray.org_y = r.origin.y, ray.org_z = r.origin.z;
  ray.dir_x = r.dir.x, ray.dir_y = r.dir.y, ray.dir_z = r.dir.z;
  ray.tnear = 0.0f;
  ray.tfar = tfar;
  ray.mask = 0xffffffffu;
  return ray;
}

}  // namespace

bool embree_available() { return true; }

EmbreeRow embree_bench(const Scene& scene, const std::vector<Ray>& primary, const std::vector<Ray>& incoherent,
                       const std::vector<Ray>& shadow, const std::vector<float>& shadow_tmax,
                       const std::vector<Hit>& our_primary, const std::vector<Hit>& our_incoherent, int threads) {
  std::vector<uint32_t> ids;
  for (uint32_t i = 0; i < scene.primitives.size(); ++i) {
    if (scene.primitives[i].kind != ShapeKind::Triangle)
      throw InputError(scene.file + ": the Embree row needs a scene of triangles only");
    ids.push_back(i);
  }
  EmbreeRow row;
  const std::string config = "threads=" + std::to_string(threads);
  RTCDevice device = rtcNewDevice(config.c_str());
  if (!device) throw std::runtime_error("Embree: rtcNewDevice failed");
  g_bytes = 0;
  g_peak = 0;
  rtcSetDeviceMemoryMonitorFunction(device, monitor, nullptr);
  RTCScene rtc = rtcNewScene(device);
  RTCGeometry geom = rtcNewGeometry(device, RTC_GEOMETRY_TYPE_TRIANGLE);
  auto* v = static_cast<float*>(
      rtcSetNewGeometryBuffer(geom, RTC_BUFFER_TYPE_VERTEX, 0, RTC_FORMAT_FLOAT3, 12, 3 * ids.size()));
  auto* index =
      static_cast<unsigned*>(rtcSetNewGeometryBuffer(geom, RTC_BUFFER_TYPE_INDEX, 0, RTC_FORMAT_UINT3, 12, ids.size()));
  for (size_t t = 0; t < ids.size(); ++t) {
    const Primitive& p = scene.primitives[ids[t]];
    const Vec3 corners[3] = {p.a, p.b, p.c};
    for (int k = 0; k < 3; ++k) {
      v[9 * t + 3 * k] = corners[k].x, v[9 * t + 3 * k + 1] = corners[k].y, v[9 * t + 3 * k + 2] = corners[k].z;
      index[3 * t + k] = static_cast<unsigned>(3 * t + k);
    }
  }
  const auto start = std::chrono::steady_clock::now();
  rtcCommitGeometry(geom);
  rtcAttachGeometry(rtc, geom);
  rtcReleaseGeometry(geom);
  rtcCommitScene(rtc);
  row.build_seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  row.megabytes = static_cast<double>(g_peak.load()) / 1048576.0;

  const auto closest = [&](const std::vector<Ray>& rays, const std::vector<Hit>& ours, double& rate) {
    std::vector<uint32_t> prim(rays.size());
    const auto t0 = std::chrono::steady_clock::now();
#pragma omp parallel for schedule(dynamic, 1024) num_threads(threads)
    for (int64_t i = 0; i < static_cast<int64_t>(rays.size()); ++i) {
      RTCIntersectContext context;
      rtcInitIntersectContext(&context);
      RTCRayHit rh{};
      rh.ray = to_rtc(rays[i], kInfinity);
      rh.hit.geomID = RTC_INVALID_GEOMETRY_ID;
      rtcIntersect1(rtc, &context, &rh);
      prim[i] = rh.hit.geomID == RTC_INVALID_GEOMETRY_ID ? kNoHit : ids[rh.hit.primID];
    }
    rate = mrays(rays.size(), t0);
    size_t same = 0;
    for (size_t i = 0; i < rays.size(); ++i) same += prim[i] == ours[i].prim;
    return same;
  };
  const size_t same = closest(primary, our_primary, row.primary) + closest(incoherent, our_incoherent, row.incoherent);
  row.same_primitive = static_cast<double>(same) / static_cast<double>(primary.size() + incoherent.size());

  const auto t0 = std::chrono::steady_clock::now();
#pragma omp parallel for schedule(dynamic, 1024) num_threads(threads)
  for (int64_t i = 0; i < static_cast<int64_t>(shadow.size()); ++i) {
    RTCIntersectContext context;
    rtcInitIntersectContext(&context);
    RTCRay ray = to_rtc(shadow[i], float_of_bits(bits_of(shadow_tmax[i]) - 1u));
    rtcOccluded1(rtc, &context, &ray);
  }
  row.shadow = mrays(shadow.size(), t0);
  rtcReleaseScene(rtc);
  rtcReleaseDevice(device);
  return row;
}

}  // namespace tracer
