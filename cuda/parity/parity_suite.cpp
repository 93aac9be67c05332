#include "parity_suite.h"

#include <chrono>
#include <cstdio>

#include "cpu_stream.h"
#include "io/sha1.h"
#include "lbvh_gpu.h"
#include "parallel_for.h"
#include "parity_gpu.h"
#include "parity_inputs.h"

namespace tracer::parity {
namespace {

constexpr uint32_t kMaxParityInputs = 1u << 24;

template <class T>
void hash_into(Sha1& sha, const std::vector<T>& v) {
  sha.append(v.data(), v.size() * sizeof(T));
}

template <class T>
std::string sha1_of(const std::vector<T>& v) {
  Sha1 sha;
  hash_into(sha, v);
  return sha.hex_digest();
}

// The answers of `queries`: fn(query) for each, on the CPU's threads.
template <class A, class Q, class Fn>
std::vector<A> on_cpu(const std::vector<Q>& queries, unsigned threads, Fn fn) {
  std::vector<A> out(queries.size());
  parallel_for(queries.size(), threads, [&](size_t i) { out[i] = fn(queries[i]); });
  return out;
}

template <class A>
void set_answers(ParityAnswers& r, const std::vector<A>& answers) {
  r.answer_size = sizeof(A);
  r.answers.assign(reinterpret_cast<const char*>(answers.data()), answers.size() * sizeof(A));
  r.answers_sha1 = sha1_of(answers);
}

std::vector<uint32_t> every_pixel(const SceneView& view) {
  std::vector<uint32_t> pixels(static_cast<size_t>(view.settings.width) * view.settings.height);
  for (size_t i = 0; i < pixels.size(); ++i) pixels[i] = static_cast<uint32_t>(i);
  return pixels;
}

// A Stream case's view: the stream schedule at the case's width.
SceneView stream_view(const ParityCase& c) {
  SceneView view = c.scene.view();
  view.settings.schedule = Schedule::Stream;
  view.settings.stream_width = c.spec.count;
  return view;
}

}  // namespace

ParityAnswers reference_parity_answers(const ParityCase& c, unsigned threads) {
  if (c.spec.kind != ParityKind::Stream) return evaluate_parity_case(c, false, threads);
  const SceneView view = stream_view(c);
  const std::vector<uint32_t> pixels = every_pixel(view);
  const uint32_t spp = view.settings.spp, width = view.settings.width;
  ParityAnswers r;
  r.inputs = pixels.size() * spp, r.inputs_sha1 = sha1_of(pixels);
  std::vector<Vec3> samples(r.inputs);
  parallel_for(samples.size(), threads, [&](size_t g) {
    const uint32_t p = static_cast<uint32_t>(g / spp);
    RayCounts counts = {0, 0, 0};
    samples[g] = render_sample(view, p % width, p / width, static_cast<uint32_t>(g % spp), counts);
  });
  set_answers(r, samples);
  return r;
}

ParityAnswers evaluate_parity_case(const ParityCase& c, bool on_gpu, unsigned threads) {
  const ParitySpec& s = c.spec;
  ParityAnswers r;
  // Runs `evaluate` (the answers on the device), adding its wall time to r.seconds.
  const auto timed = [&r](auto evaluate) {
    const auto start = std::chrono::steady_clock::now();
    auto answers = evaluate();
    r.seconds += std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    return answers;
  };
  switch (s.kind) {
    case ParityKind::Math: {
      const MathFunction f = static_cast<MathFunction>(s.function);
      const MathInputs in = math_inputs(f, s.seed, s.count, s.count / 2);
      Sha1 sha;
      hash_into(sha, in.a);
      hash_into(sha, in.b);
      r.inputs = in.a.size(), r.inputs_sha1 = sha.hex_digest();
      set_answers(r, timed([&] {
                    if (on_gpu) return gpu_math(f, in.a, in.b);
                    std::vector<float> out(in.a.size());
                    parallel_for(out.size(), threads, [&](size_t i) { out[i] = eval_math(f, in.a[i], in.b[i]); });
                    return out;
                  }));
      break;
    }
    case ParityKind::Philox: {
      const std::vector<PhiloxQuery> q = philox_inputs(s.seed, s.count);
      r.inputs = q.size(), r.inputs_sha1 = sha1_of(q);
      set_answers(r, timed([&] { return on_gpu ? gpu_philox(q) : on_cpu<Philox4>(q, threads, eval_philox); }));
      break;
    }
    case ParityKind::Shapes: {
      const std::vector<ShapeQuery> q = shape_inputs(s.seed, s.count);
      r.inputs = q.size(), r.inputs_sha1 = sha1_of(q);
      set_answers(r, timed([&] { return on_gpu ? gpu_shapes(q) : on_cpu<ShapeAnswer>(q, threads, eval_shape); }));
      break;
    }
    case ParityKind::Bsdf: {
      const std::vector<BsdfQuery> q = bsdf_inputs(s.seed, s.count);
      r.inputs = q.size(), r.inputs_sha1 = sha1_of(q);
      set_answers(r, timed([&] { return on_gpu ? gpu_bsdfs(q) : on_cpu<BsdfAnswer>(q, threads, eval_bsdf_case); }));
      break;
    }
    case ParityKind::Trace: {
      const std::vector<Ray> rays = ray_inputs(s.seed, s.count, s.lo, s.hi);
      r.inputs = rays.size(), r.inputs_sha1 = sha1_of(rays);
      const SceneView view = c.scene.view();
      set_answers(r, timed([&] {
                    return on_gpu ? gpu_trace(c.scene.arrays, view, rays)
                                  : on_cpu<TraceAnswer>(rays, threads,
                                                        [&](const Ray& ray) { return eval_trace(view, ray); });
                  }));
      break;
    }
    case ParityKind::Sample: {
      const SceneView view = c.scene.view();
      const std::vector<uint32_t> pixels = every_pixel(view);
      r.inputs = pixels.size(), r.inputs_sha1 = sha1_of(pixels);
      set_answers(r, timed([&] {
                    return on_gpu ? gpu_samples(c.scene.arrays, view)
                                  : on_cpu<SampleAnswer>(pixels, threads,
                                                         [&](uint32_t p) { return eval_sample(view, p); });
                  }));
      break;
    }
    case ParityKind::Stream: {
      const SceneView view = stream_view(c);
      const std::vector<uint32_t> pixels = every_pixel(view);
      r.inputs = pixels.size() * view.settings.spp, r.inputs_sha1 = sha1_of(pixels);
      set_answers(r, timed([&] {
                    if (on_gpu) return gpu_stream_samples(c.scene.arrays, view);
                    std::vector<Vec3> samples(r.inputs);
                    StreamTarget target = {nullptr, pixels.size(), 0u, view.settings.spp, nullptr, nullptr, nullptr};
                    target.samples = samples.data();
                    RayCounts rays{};
                    StreamStats stats;
                    render_stream_on_cpu(view, target, threads, rays, stats);
                    return samples;
                  }));
      break;
    }
    case ParityKind::Lbvh: {
      const LbvhInput in = lbvh_inputs(s.seed, s.count);
      Sha1 sha;
      hash_into(sha, in.boxes);
      hash_into(sha, in.centroids);
      hash_into(sha, in.ids);
      r.inputs = in.boxes.size(), r.inputs_sha1 = sha.hex_digest();
      const LbvhTree tree = timed([&] {
        if (!on_gpu) return build_lbvh_tree(in, [&](size_t n, const auto& fn) { parallel_for(n, threads, fn, 1024); });
        GpuLbvh g = build_lbvh_on_gpu(in);
        char note[96];
        std::snprintf(note, sizeof note, "device build %.6f s", g.build_seconds);
        r.note = note;
        return std::move(g.tree);
      });
      std::vector<uint32_t> words(tree.nodes.size() * sizeof(BvhNode) / 4 + tree.order.size());
      std::memcpy(words.data(), tree.nodes.data(), tree.nodes.size() * sizeof(BvhNode));
      std::memcpy(words.data() + tree.nodes.size() * sizeof(BvhNode) / 4, tree.order.data(), tree.order.size() * 4);
      set_answers(r, words);
      break;
    }
    case ParityKind::Adaptive: {
      const std::vector<AdaptiveQuery> q = adaptive_inputs(s.seed, s.count);
      r.inputs = q.size(), r.inputs_sha1 = sha1_of(q);
      set_answers(r,
                  timed([&] { return on_gpu ? gpu_adaptive(q) : on_cpu<AdaptiveAnswer>(q, threads, eval_adaptive); }));
      break;
    }
    default: throw InputError(c.name + ": unknown parity case kind " + std::to_string(static_cast<uint32_t>(s.kind)));
  }
  return r;
}

std::string describe_differences(const ParityAnswers& expected, const ParityAnswers& got, size_t limit) {
  if (expected.answer_size != got.answer_size || expected.answers.size() != got.answers.size())
    return "answer sizes differ";
  std::string text;
  const size_t n = expected.answer_size ? expected.answers.size() / expected.answer_size : 0;
  size_t differing = 0;
  for (size_t i = 0; i < n; ++i) {
    const size_t at = i * expected.answer_size;
    if (expected.answers.compare(at, expected.answer_size, got.answers, at, expected.answer_size) == 0) continue;
    if (++differing > limit) continue;
    text += "  input " + std::to_string(i) + ": expected";
    char byte[4];
    for (size_t b = 0; b < expected.answer_size; ++b)
      std::snprintf(byte, sizeof byte, " %02x", static_cast<unsigned char>(expected.answers[at + b])), text += byte;
    text += ", got";
    for (size_t b = 0; b < expected.answer_size; ++b)
      std::snprintf(byte, sizeof byte, " %02x", static_cast<unsigned char>(got.answers[at + b])), text += byte;
    text += "\n";
  }
  return std::to_string(differing) + " of " + std::to_string(n) + " answers differ\n" + text;
}

BundleFile encode_parity_case(const ParityCase& c, const ParityAnswers& cpu) {
  BundleFile file;
  if (c.spec.kind == ParityKind::Trace || c.spec.kind == ParityKind::Sample || c.spec.kind == ParityKind::Stream)
    file = encode_scene_bundle(c.scene);
  file.kind = "parity";
  file.add_one("case", c.spec);
  file.add("name", std::vector<char>(c.name.begin(), c.name.end()));
  file.add("inputs_sha1", std::vector<char>(cpu.inputs_sha1.begin(), cpu.inputs_sha1.end()));
  file.add("answers_sha1", std::vector<char>(cpu.answers_sha1.begin(), cpu.answers_sha1.end()));
  return file;
}

StoredParityCase read_parity_case(const std::string& path) {
  const BundleFile file = read_bundle(path, "parity");
  StoredParityCase s;
  s.parity.spec = file.get_one<ParitySpec>("case", path);
  const auto text = [&](const char* name) {
    const std::vector<char> v = file.get<char>(name, path);
    return std::string(v.begin(), v.end());
  };
  s.parity.name = text("name");
  s.inputs_sha1 = text("inputs_sha1");
  s.answers_sha1 = text("answers_sha1");
  const ParitySpec& spec = s.parity.spec;
  if (static_cast<uint32_t>(spec.kind) > static_cast<uint32_t>(ParityKind::Bsdf) ||
      spec.function >= kMathFunctionCount || spec.count > kMaxParityInputs ||
      (spec.kind == ParityKind::Stream && spec.count == 0))
    throw InputError(path + ": parity case " + s.parity.name + " has kind " +
                     std::to_string(static_cast<uint32_t>(spec.kind)) + ", function " + std::to_string(spec.function) +
                     ", count " + std::to_string(spec.count) + " (kinds 0-8, functions 0-8, counts up to 2^24)");
  if (s.parity.spec.kind == ParityKind::Trace || s.parity.spec.kind == ParityKind::Sample ||
      s.parity.spec.kind == ParityKind::Stream)
    s.parity.scene = decode_scene_bundle(file, path);
  return s;
}

}  // namespace tracer::parity
