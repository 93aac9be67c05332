#!/usr/bin/env python3
"""Where the path tracer's time goes, by kernel header: samples a CPU render with `perf record`
and charges each sample to the innermost inlined frame that lies in a kernel header other
than the generic math (vec3, platform, detmath, GLM, SSE intrinsics), via `addr2line -i`.

  cmake -S . -B /tmp/build-prof -DCMAKE_BUILD_TYPE=RelWithDebInfo \\
        "-DCMAKE_CXX_FLAGS_RELWITHDEBINFO=-O3 -g -DNDEBUG" -DTRACER_WITH_CUDA=OFF \\
        -DTRACER_CPU_VARIANTS=OFF -DTRACER_DEVICE_SEMANTICS_RUNNER=OFF
  cmake --build /tmp/build-prof --target tracer
  python3 ci/profile_path.py /tmp/build-prof/tracer scenes/cornell-box-path.json --sampler sobol --spp 64

Everything after the binary is handed to `tracer render` (with --threads 1 and an output in
a temporary folder). Needs perf (perf_event_paranoid 2 or lower) and binutils' addr2line.
The build is the generic kernel (TRACER_CPU_VARIANTS=OFF), as the debug information of one
kernel is what makes the frames readable."""
import collections
import os
import re
import subprocess
import sys
import tempfile

GENERIC = ("kernel/base/vec3.h", "kernel/base/platform.h", "kernel/base/detmath.h", "kernel/base/float_to_int.h",
           "glm/", "intrin.h", "cmath", "bits/")
GROUPS = [("kernel/accel/", "traversal (kernel/accel)"), ("kernel/geom/", "intersection, offsets, uv (kernel/geom)"),
          ("kernel/base/sobol.h", "random numbers"), ("kernel/base/philox.h", "random numbers"),
          ("kernel/camera/", "random numbers"), ("kernel/material/", "BSDFs (kernel/material)"),
          ("kernel/light/", "lights (kernel/light)"), ("kernel/shading/", "surface, textures, sampling (kernel/shading)"),
          ("kernel/integrator/", "integrator (kernel/integrator)"), ("kernel/base/", "film and the rest of kernel/base")]


def text_segment_delta(binary):
    """Address minus file offset of the binary's executable LOAD segment (`readelf -lW`)."""
    headers = subprocess.run(["readelf", "-lW", binary], capture_output=True, text=True, check=True).stdout
    for line in headers.splitlines():
        f = line.split()
        if f and f[0] == "LOAD" and "E" in f[6:-1]:
            return int(f[2], 16) - int(f[1], 16)
    sys.exit(binary + ": no executable LOAD segment in `readelf -lW`")


def main():
    if len(sys.argv) < 3:
        sys.exit(__doc__)
    binary, render_args = os.path.abspath(sys.argv[1]), sys.argv[2:]
    with tempfile.TemporaryDirectory() as tmp:
        data = os.path.join(tmp, "perf.data")
        subprocess.run(["perf", "record", "-q", "-F", "4000", "-o", data, binary, "render"] + render_args +
                       ["--threads", "1", "--quiet", "-o", os.path.join(tmp, "out.exr")], check=True,
                       stdout=subprocess.DEVNULL)
        script = subprocess.run(["perf", "script", "-i", data, "--show-mmap-events", "-F", "ip,dso"],
                                capture_output=True, text=True, check=True).stdout.splitlines()
    # The executable segment's addresses are its file offsets plus a delta the linker chose (0
    # with GNU ld, a page with lld): perf gives file offsets, addr2line wants addresses.
    delta = text_segment_delta(binary)
    base = None
    counts, outside = collections.Counter(), 0
    for line in script:
        m = re.search(r"MMAP2? .*\[(0x[0-9a-f]+)\((0x[0-9a-f]+)\) @ (0x[0-9a-f]+).*r-xp (\S+)$", line)
        if m and os.path.abspath(m.group(4)) == binary:
            base = int(m.group(1), 16) - int(m.group(3), 16) - delta
            continue
        parts = line.split()
        if len(parts) == 2 and base is not None and parts[1] == "(" + binary + ")":
            counts[int(parts[0], 16) - base] += 1
        elif len(parts) == 2:
            outside += 1
    addresses = sorted(counts)
    lines = subprocess.run(["addr2line", "-a", "-i", "-f", "-e", binary] + [hex(a) for a in addresses],
                           capture_output=True, text=True, check=True).stdout.splitlines()
    frames, at, i = collections.defaultdict(list), None, 0
    while i < len(lines):
        if lines[i].startswith("0x"):
            at, i = int(lines[i], 16), i + 1
            continue
        frames[at].append(lines[i + 1].split(":")[0] if i + 1 < len(lines) else "?")
        i += 2
    by_file, by_group = collections.Counter(), collections.Counter()
    for a, n in counts.items():
        fs = frames.get(a, ["?"])
        pick = next((f for f in fs if not any(g in f for g in GENERIC)), fs[0])
        by_file[pick.split("tracer/kernel/")[-1] if "tracer/kernel/" in pick else "outside the kernel"] += n
        by_group[next((name for key, name in GROUPS if key in pick), "outside the kernel")] += n
    total = sum(counts.values()) + outside
    print("%d samples; outside the binary (libraries, the system): %.1f %%" % (total, 100.0 * outside / total))
    for name, n in by_group.most_common():
        print("%-48s %6.1f %%" % (name, 100.0 * n / total))
    print()
    for name, n in by_file.most_common(16):
        print("  %-46s %6.1f %%" % (name, 100.0 * n / total))


if __name__ == "__main__":
    main()
