#!/usr/bin/python3
"""Groups a `perf report --sort dso,symbol --stdio` listing (on stdin) into primflow's stages.

    perf report ... | python3 bench/profile_stages.py SCENE    -> CSV rows scene,stage,share

Only primflow's samples count: llvmpipe's (libOSMesa, its JIT code, libLLVM outside a compile),
the benchmark's own scene building and the kernel's are left out, and each stage's share is a
percentage of the rest. Used by bench/run_profile.
"""
import csv
import re
import sys

# (stage, test on "dso symbol"), first match wins.
STAGES = [
    ("pixel programs (native code)", lambda d, s: s.startswith("pf_pixel_")),
    ("block rejection", lambda d, s: s.startswith("pf_verdict_") or s.startswith("pf_block_verdicts_")
     or "BlockRejection" in s or "regionVerdict" in s or "regionMemo" in s or "blockVerdict" in s
     or "rejectsRegion" in s),
    ("pixel programs (interpreter)", lambda d, s: "PixelExecutor::execute" in s or "::run<" in s or "::fused<" in s
     or "decodeProgram" in s),
    ("block calls (executor, native arguments)", lambda d, s: "PixelExecutor::" in s or "NativeBlocks::" in s
     or "popcount" in s),
    ("gang blocks (record spread)", lambda d, s: "spread" in s or "GangBlock::" in s),
    ("setup", lambda d, s: s.startswith("pf_setup_") or "Setup" in s or "::batch<" in s),
    ("shading pass", lambda d, s: "shadeTile" in s or "LightingEquation" in s or "shadeRun" in s),
    ("tile walk, binning, depth culling", lambda d, s: "runTile" in s or "binInstance" in s or "CoarseDepth" in s
     or "depthPassMask" in s or "submitInstances" in s or "Renderer::" in s or "WorkerPool" in s),
    ("API (glBegin .. glEnd)", lambda d, s: s.startswith("pfgl") or "sequencePoint" in s or "immediate" in s.lower()),
    ("LLVM (compiling)", lambda d, s: "libLLVM" in d),
]
NOT_PRIMFLOW = ("libOSMesa", "[JIT]", "libgallium", "libglapi", "[kernel", "libc.so", "ld-linux", "libstdc++",
                "libm.so", "libgcc")


def main():
    scene = sys.argv[1]
    shares = {}
    for line in sys.stdin:
        m = re.match(r"\s*([\d.]+)%\s+(\S+)\s+\[\.\]\s+(.*)$", line)
        if not m:
            continue
        pct, dso, sym = float(m.group(1)), m.group(2), m.group(3).strip()
        if any(dso.startswith(x) for x in NOT_PRIMFLOW) or sym.startswith("pfbench::") or sym.startswith("std::"):
            continue
        stage = next((name for name, test in STAGES if test(dso, sym)), "other")
        shares[stage] = shares.get(stage, 0.0) + pct
    total = sum(shares.values())
    out = csv.writer(sys.stdout, lineterminator="\n")
    for name, _ in STAGES + [("other", None)]:
        if name in shares and total > 0:
            out.writerow([scene, name, f"{100.0 * shares[name] / total:.1f}"])


if __name__ == "__main__":
    main()
