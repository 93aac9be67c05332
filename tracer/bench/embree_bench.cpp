#include "bench/embree_bench.h"

#include <embree3/rtcore.h>
#include <omp.h>

#include <atomic>
#include <chrono>
#include <string>
#include <thread>

#include "bench/bench_common.h"
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
                       const std::vector<Hit>& our_primary, const std::vector<Hit>& our_incoherent, int threads,
                       uint32_t repeats, const std::function<double()>& our_build) {
  for (const Primitive& p : scene.primitives)
    if (p.kind != ShapeKind::Triangle)
      throw InputError(scene.file + ": the Embree row needs a scene of triangles only");
  EmbreeRow row;
  const std::string config = "threads=" + std::to_string(threads);
  RTCDevice device = rtcNewDevice(config.c_str());
  if (!device) throw std::runtime_error("Embree: rtcNewDevice failed");
  g_bytes = 0;
  g_peak = 0;
  rtcSetDeviceMemoryMonitorFunction(device, monitor, nullptr);
  // One scene of all triangles; the commit (Embree's build) is what is timed.
  const auto build = [&](double* seconds) {
    RTCScene rtc = rtcNewScene(device);
    RTCGeometry geom = rtcNewGeometry(device, RTC_GEOMETRY_TYPE_TRIANGLE);
    const size_t n = scene.primitives.size();
    auto* v =
        static_cast<float*>(rtcSetNewGeometryBuffer(geom, RTC_BUFFER_TYPE_VERTEX, 0, RTC_FORMAT_FLOAT3, 12, 3 * n));
    auto* index =
        static_cast<unsigned*>(rtcSetNewGeometryBuffer(geom, RTC_BUFFER_TYPE_INDEX, 0, RTC_FORMAT_UINT3, 12, n));
    for (size_t t = 0; t < n; ++t) {
      const Primitive& p = scene.primitives[t];
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
    *seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    return rtc;
  };
  RTCScene rtc = nullptr;
  row.build_seconds = median_build_seconds(repeats, [&] {
    double seconds = 0;
    if (rtc) rtcReleaseScene(rtc);
    rtc = build(&seconds);
    return seconds;
  });
  row.megabytes = static_cast<double>(g_peak.load()) / 1048576.0;
  if (our_build) {  // at least `repeats` pairs; up to 50 while they fill less than 0.5 s
    // Each build starts 20 ms after the last, as a scene's one build does, from idle threads:
    // back to back, the other library's threads would still spin for work and take a core.
    const auto idle = [] { std::this_thread::sleep_for(std::chrono::milliseconds(20)); };
    row.paired_build = median_filling(repeats, 0.5, 50, [&] {
      idle();
      const double ours = our_build();
      double seconds = 0;
      rtcReleaseScene(rtc);
      idle();
      rtc = build(&seconds);
      return TimedValue{ours / seconds, ours + seconds};
    });
  }

  std::vector<uint32_t> prim;
  const auto closest = [&](const std::vector<Ray>& rays) {
    prim.assign(rays.size(), kNoHit);
    return median_of(repeats, [&] {
      const auto t0 = std::chrono::steady_clock::now();
#pragma omp parallel for schedule(dynamic, 1024) num_threads(threads)
      for (int64_t i = 0; i < static_cast<int64_t>(rays.size()); ++i) {
        RTCIntersectContext context;
        rtcInitIntersectContext(&context);
        RTCRayHit rh{};
        rh.ray = to_rtc(rays[i], kInfinity);
        rh.hit.geomID = RTC_INVALID_GEOMETRY_ID;
        rtcIntersect1(rtc, &context, &rh);
        prim[i] = rh.hit.geomID == RTC_INVALID_GEOMETRY_ID ? kNoHit : rh.hit.primID;
      }
      return mrays(rays.size(), t0);
    });
  };
  size_t same = 0;
  row.primary = closest(primary);
  for (size_t i = 0; i < primary.size(); ++i) same += prim[i] == our_primary[i].prim;
  row.incoherent = closest(incoherent);
  for (size_t i = 0; i < incoherent.size(); ++i) same += prim[i] == our_incoherent[i].prim;
  row.same_primitive = static_cast<double>(same) / static_cast<double>(primary.size() + incoherent.size());

  row.shadow = median_of(repeats, [&] {
    const auto t0 = std::chrono::steady_clock::now();
#pragma omp parallel for schedule(dynamic, 1024) num_threads(threads)
    for (int64_t i = 0; i < static_cast<int64_t>(shadow.size()); ++i) {
      RTCIntersectContext context;
      rtcInitIntersectContext(&context);
      RTCRay ray = to_rtc(shadow[i], float_of_bits(bits_of(shadow_tmax[i]) - 1u));
      rtcOccluded1(rtc, &context, &ray);
    }
    return mrays(shadow.size(), t0);
  });
  rtcReleaseScene(rtc);
  rtcReleaseDevice(device);
  return row;
}

}  // namespace tracer
