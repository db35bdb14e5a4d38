#!/usr/bin/env python3
"""Mutation campaign against the `nvv` command-line tool's mesh readers.

Builds small base meshes from the project's sample meshes (sample_meshes/*.ply, cropped so that
each run is short), writes each in every format the tool reads (PLY ascii / binary little and
big endian, OBJ, OFF, STL ascii / binary), mutates them (bit flips, byte insertions and
deletions, truncation, huge header counts, bad indices, long face lists, odd numbers) and runs
the given `nvv` on each mutant with a time limit and a memory limit. Counts exit codes,
signals, time-outs and sanitizer reports; exits non-zero when any run was killed by a signal,
timed out, printed a sanitizer report, or ended with an exit code the tool does not document
(0 ok, 2 bad arguments, 3 bad input file, 4 refused by the filter, 5 cannot write), or failed
without its one-line "nvv: <file>: <reason>" message.

Usage: mutation_campaign.py --nvv PATH [--count 2000] [--seed 1] [--workdir DIR]
                            [--timeout 30] [--memory-mb 2048] [--samples DIR] [--jobs 1]
Python 3 standard library only.
"""
import argparse
import collections
import concurrent.futures
import os
import random
import resource
import shutil
import signal
import struct
import subprocess
import sys
import tempfile
import time

DOCUMENTED_EXIT_CODES = {0: "ok", 2: "bad arguments", 3: "bad input file", 4: "refused by the filter", 5: "cannot write"}
SANITIZER_MARKERS = (b"ERROR: AddressSanitizer", b"ERROR: LeakSanitizer", b"runtime error:", b"ERROR: UndefinedBehaviorSanitizer")

# ---------------------------------------------------------------------------------------------
# Reading the sample meshes (binary_little_endian or ascii PLY, any scalar properties, one face
# list) and writing the base files.

PLY_TYPES = {"char": "b", "int8": "b", "uchar": "B", "uint8": "B", "short": "h", "int16": "h", "ushort": "H",
             "uint16": "H", "int": "i", "int32": "i", "uint": "I", "uint32": "I", "float": "f", "float32": "f",
             "double": "d", "float64": "d"}


def read_ply(path):
    data = open(path, "rb").read()
    end = data.index(b"end_header") + len(b"end_header")
    end = data.index(b"\n", end) + 1
    header = data[:end].decode("ascii", "replace").splitlines()
    fmt = None
    elements = []
    for line in header:
        t = line.split()
        if not t:
            continue
        if t[0] == "format":
            fmt = t[1]
        elif t[0] == "element":
            elements.append((t[1], int(t[2]), []))
        elif t[0] == "property":
            elements[-1][2].append(t[1:])
    verts, faces = [], []
    if fmt == "ascii":
        tokens = data[end:].split()
        pos = 0
        for name, count, props in elements:
            for _ in range(count):
                rec = {}
                for p in props:
                    if p[0] == "list":
                        n = int(tokens[pos]); pos += 1
                        rec[p[3]] = [int(x) for x in tokens[pos:pos + n]]; pos += n
                    else:
                        rec[p[1]] = float(tokens[pos]); pos += 1
                if name == "vertex":
                    verts.append((rec["x"], rec["y"], rec["z"]))
                elif name == "face":
                    faces.append(rec.get("vertex_indices", rec.get("vertex_index")))
        return verts, faces
    e = "<" if fmt == "binary_little_endian" else ">"
    pos = end
    for name, count, props in elements:
        for _ in range(count):
            rec = {}
            for p in props:
                if p[0] == "list":
                    ct, it = PLY_TYPES[p[1]], PLY_TYPES[p[2]]
                    (n,) = struct.unpack_from(e + ct, data, pos); pos += struct.calcsize(ct)
                    rec[p[3]] = list(struct.unpack_from(e + it * n, data, pos)); pos += struct.calcsize(it) * n
                else:
                    c = PLY_TYPES[p[0]]
                    (rec[p[1]],) = struct.unpack_from(e + c, data, pos); pos += struct.calcsize(c)
            if name == "vertex":
                verts.append((rec["x"], rec["y"], rec["z"]))
            elif name == "face":
                faces.append(rec.get("vertex_indices", rec.get("vertex_index")))
    return verts, faces


def crop(verts, faces, max_vertices):
    """The faces that use only the first max_vertices vertices, and those vertices, re-indexed."""
    keep = [f for f in faces if max(f) < max_vertices]
    used = sorted({i for f in keep for i in f})
    remap = {old: new for new, old in enumerate(used)}
    return [verts[i] for i in used], [[remap[i] for i in f] for f in keep]


def g(x):
    return "%.9g" % x


def write_formats(verts, faces):
    """{extension-tag: bytes} for every format the tool reads."""
    out = {}
    xyz = "property float x\nproperty float y\nproperty float z\n"
    head = "element vertex %d\n%selement face %d\nproperty list uchar int vertex_indices\nend_header\n" % (
        len(verts), xyz, len(faces))
    body = "".join("%s %s %s\n" % tuple(map(g, v)) for v in verts)
    body += "".join("%d %s\n" % (len(f), " ".join(map(str, f))) for f in faces)
    out["ascii.ply"] = ("ply\nformat ascii 1.0\n" + head + body).encode()
    for tag, e in (("le.ply", "<"), ("be.ply", ">")):
        enc = "binary_little_endian" if e == "<" else "binary_big_endian"
        b = bytearray(("ply\nformat %s 1.0\n" % enc + head).encode())
        for v in verts:
            b += struct.pack(e + "3f", *v)
        for f in faces:
            b += struct.pack(e + "B%di" % len(f), len(f), *f)
        out[tag] = bytes(b)
    out["obj"] = ("# base\n" + "".join("v %s %s %s\n" % tuple(map(g, v)) for v in verts) +
                  "".join("f %s\n" % " ".join(str(i + 1) for i in f) for f in faces)).encode()
    out["off"] = ("OFF\n%d %d 0\n" % (len(verts), len(faces)) + body).encode()
    s = "solid base\n"
    b = bytearray(b"binary base".ljust(80, b" ")) + struct.pack("<I", len(faces))
    for f in faces:
        s += "facet normal 0 0 0\n outer loop\n"
        b += struct.pack("<3f", 0, 0, 0)
        for i in f[:3]:
            s += "  vertex %s %s %s\n" % tuple(map(g, verts[i]))
            b += struct.pack("<3f", *verts[i])
        s += " endloop\nendfacet\n"
        b += b"\0\0"
    out["ascii.stl"] = (s + "endsolid base\n").encode()
    out["bin.stl"] = bytes(b)
    return out


# ---------------------------------------------------------------------------------------------
# Mutations. Each takes (rng, data, tag) and returns new bytes.

HUGE = [b"4294967295", b"2147483647", b"2147483648", b"100000000", b"18446744073709551615", b"-1", b"-2147483648",
        b"9999999999999999999999", b"1e9"]
ODD_NUMBERS = [b"nan", b"-nan", b"inf", b"-inf", b"0x1p3", b"1e999", b"-1e-999", b"1e-45", b"NAN(1)", b"infinity",
               b"0x", b"1e", b"--1", b"1.5.5", b"", b"\x00", b"3.4028236e38"]
BAD_INDICES = [b"-1", b"0", b"-2147483648", b"2147483647", b"2147483648", b"4294967296", b"99999999999",
               b"-99999999999999999999", b"1/2/3", b"//", b"x"]


def m_bitflip(rng, d, tag):
    if not d:  # mutations chain: an earlier one may have left nothing
        return bytes([rng.randrange(256)])
    b = bytearray(d)
    for _ in range(rng.randint(1, 8)):
        i = rng.randrange(len(b))
        b[i] ^= 1 << rng.randrange(8)
    return bytes(b)


def m_insert(rng, d, tag):
    i = rng.randrange(len(d) + 1)
    if rng.random() < 0.5:
        ins = bytes(rng.randrange(256) for _ in range(rng.randint(1, 16)))
    elif d:  # a copied chunk of the file itself
        a = rng.randrange(len(d))
        ins = d[a:a + rng.randint(1, 200)]
    else:
        ins = b"\n"
    return d[:i] + ins + d[i:]


def m_delete(rng, d, tag):
    if not d:
        return d
    i = rng.randrange(len(d))
    return d[:i] + d[i + rng.randint(1, 64):]


def m_truncate(rng, d, tag):
    return d[:rng.randrange(len(d))] if d else d


def m_huge_count(rng, d, tag):
    h = rng.choice(HUGE)
    if tag.endswith("ply"):
        key = rng.choice([b"element vertex ", b"element face "])
        i = d.find(key)
        j = d.find(b"\n", i)
        return d[:i + len(key)] + h + d[j:]
    if tag == "off":
        j = d.find(b"\n", 4)
        parts = d[4:j].split()
        parts[rng.randrange(2)] = h
        return d[:4] + b" ".join(parts) + d[j:]
    if tag == "bin.stl":
        return d[:80] + struct.pack("<I", rng.choice([0xFFFFFFFF, 100000000, 2 ** 31, len(d) // 50 + 1])) + d[84:]
    if tag == "obj":
        return d + b"f 1 2 " + h + b"\n"
    return d.replace(b"endloop", b"vertex 1 2\nendloop", 1)


def m_bad_index(rng, d, tag):
    if tag == "obj" or tag == "off" or tag == "ascii.ply":
        lines = d.split(b"\n")
        cand = [k for k, l in enumerate(lines) if (l.startswith(b"f ") if tag == "obj" else l[:2] in (b"3 ", b"4 "))]
        if not cand:
            return m_bitflip(rng, d, tag)
        k = rng.choice(cand)
        t = lines[k].split()
        t[rng.randrange(1, len(t))] = rng.choice(BAD_INDICES)
        lines[k] = b" ".join(t)
        return b"\n".join(lines)
    if tag in ("le.ply", "be.ply"):
        e = "<" if tag == "le.ply" else ">"
        # Overwrite one int32 somewhere in the last third of the data (the face records).
        if len(d) < 16:
            return m_bitflip(rng, d, tag)
        b = bytearray(d)
        i = rng.randrange(len(b) * 2 // 3, len(b) - 4)
        struct.pack_into(e + "i", b, i, rng.choice([-1, -2 ** 31, 2 ** 31 - 1, len(d), 1 << 20]))
        return bytes(b)
    return m_bitflip(rng, d, tag)


def m_long_list(rng, d, tag):
    n = rng.choice([100, 255, 256, 1000, 70000])
    idx = [rng.randrange(3) for _ in range(n)]
    if tag == "obj":
        return d + b"f " + b" ".join(str(i + 1).encode() for i in idx) + b"\n"
    if tag == "off":
        return d + str(n).encode() + b" " + b" ".join(str(i).encode() for i in idx) + b"\n"
    if tag == "ascii.ply":
        body = str(min(n, 255)).encode() + b" " + b" ".join(str(i).encode() for i in idx[:255]) + b"\n"
        return d.rstrip(b"\n").rsplit(b"\n", 1)[0] + b"\n" + body
    if tag in ("le.ply", "be.ply"):
        e = "<" if tag == "le.ply" else ">"
        # Replace the last face (a triangle: 13 bytes) by a longer one; a wrong count now and then.
        m = min(n, 255)
        count = m if rng.random() < 0.7 else rng.randrange(256)
        return d[:-13] + struct.pack(e + "B", count) + struct.pack(e + "%di" % m, *idx[:m])
    if tag == "ascii.stl":
        extra = b"".join(b"vertex 0 0 %d\n" % i for i in range(min(n, 1000)))
        return d.replace(b"endloop", extra + b"endloop", 1)
    return m_insert(rng, d, tag)


def m_odd_number(rng, d, tag):
    if tag in ("le.ply", "be.ply", "bin.stl"):
        if len(d) < 8:
            return m_bitflip(rng, d, tag)
        b = bytearray(d)
        for _ in range(rng.randint(1, 4)):
            i = rng.randrange(max(1, len(b) - 4))
            struct.pack_into("<f", b, i, rng.choice([float("nan"), float("inf"), -float("inf"), 3.4e38, 1e-45, 0.0]))
        return bytes(b)
    toks = d.split(b" ")
    for _ in range(rng.randint(1, 4)):
        toks[rng.randrange(len(toks))] = rng.choice(ODD_NUMBERS)
    return b" ".join(toks)


MUTATIONS = [("bitflip", m_bitflip), ("insert", m_insert), ("delete", m_delete), ("truncate", m_truncate),
             ("huge_count", m_huge_count), ("bad_index", m_bad_index), ("long_list", m_long_list),
             ("odd_number", m_odd_number)]


# ---------------------------------------------------------------------------------------------

def is_sanitized(nvv):
    with open(nvv, "rb") as f:
        return b"__asan_init" in f.read()  # statically or dynamically linked runtime


def run_one(nvv, path, out, timeout, memory_mb, sanitized):
    env = dict(os.environ)
    if sanitized:
        # AddressSanitizer reserves terabytes of address space: RLIMIT_AS cannot bound it, its own
        # RSS limit does.
        env["ASAN_OPTIONS"] = "abort_on_error=0:detect_leaks=1:hard_rss_limit_mb=%d:allocator_may_return_null=0" % memory_mb
        env["UBSAN_OPTIONS"] = "print_stacktrace=1:halt_on_error=1"

    def limit():
        if not sanitized:
            b = memory_mb * 1024 * 1024
            resource.setrlimit(resource.RLIMIT_AS, (b, b))
        resource.setrlimit(resource.RLIMIT_CORE, (0, 0))

    t0 = time.time()
    try:
        p = subprocess.run([nvv, "--threads", "1", "--quiet", path, out], stdin=subprocess.DEVNULL, stdout=subprocess.PIPE,
                           stderr=subprocess.PIPE, timeout=timeout, preexec_fn=limit, env=env)
        return p.returncode, p.stderr, time.time() - t0
    except subprocess.TimeoutExpired as e:
        return None, e.stderr or b"", time.time() - t0


def main():
    here = os.path.dirname(os.path.abspath(__file__))
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--nvv", required=True, help="the nvv binary to test")
    ap.add_argument("--count", type=int, default=2000, help="number of mutated files (default 2000)")
    ap.add_argument("--seed", type=int, default=1)
    ap.add_argument("--workdir", help="where the files go (default: a temporary folder, removed at the end)")
    ap.add_argument("--timeout", type=float, default=30.0, help="seconds per run (default 30)")
    ap.add_argument("--memory-mb", type=int, default=2048, help="memory limit per run (default 2048)")
    ap.add_argument("--samples", default=os.path.join(here, "..", "..", "sample_meshes"))
    ap.add_argument("--max-vertices", type=int, default=300, help="crop each sample to this many vertices")
    ap.add_argument("--jobs", type=int, default=1)
    args = ap.parse_args()

    nvv = os.path.abspath(args.nvv)
    sanitized = is_sanitized(nvv)
    work = args.workdir or tempfile.mkdtemp(prefix="nvv_mutation_")
    os.makedirs(work, exist_ok=True)
    keep_dir = os.path.join(work, "findings")
    rng = random.Random(args.seed)

    bases = []
    samples = sorted(f for f in os.listdir(args.samples) if f.endswith(".ply"))
    if not samples:
        sys.exit("no sample meshes in %s" % args.samples)
    for name in samples:
        verts, faces = crop(*read_ply(os.path.join(args.samples, name)), args.max_vertices)
        if not faces:
            continue
        for tag, data in write_formats(verts, faces).items():
            bases.append((name[:-4], tag, data))
    print("nvv: %s (%s)" % (nvv, "AddressSanitizer + UBSan" if sanitized else "not sanitized"))
    print("base files: %d (%d samples x %d formats), mutants: %d, time limit %g s, memory limit %d MB"
          % (len(bases), len(bases) // 7, 7, args.count, args.timeout, args.memory_mb))

    # Every base file must load and run: otherwise the campaign would test nothing.
    cases = []
    for k, (sample, tag, data) in enumerate(bases):
        cases.append(("base", sample, tag, data))
    for k in range(args.count):
        sample, tag, data = rng.choice(bases)
        kinds = []
        for _ in range(1 if rng.random() < 0.7 else rng.randint(2, 3)):
            kind, fn = rng.choice(MUTATIONS)
            if not data:
                break
            data = fn(rng, data, tag)
            kinds.append(kind)
        cases.append(("+".join(kinds) or "empty", sample, tag, data))

    codes = collections.Counter()
    by_kind = collections.defaultdict(collections.Counter)
    problems = []
    start = time.time()

    def job(i):
        kind, sample, tag, data = cases[i]
        ext = tag.rsplit(".", 1)[-1]
        path = os.path.join(work, "case%05d.%s" % (i, ext))
        out = os.path.join(work, "case%05d.out.ply" % i)
        with open(path, "wb") as f:
            f.write(data)
        rc, err, secs = run_one(nvv, path, out, args.timeout, args.memory_mb, sanitized)
        return i, path, out, rc, err, secs

    slowest = (0.0, "")
    with concurrent.futures.ThreadPoolExecutor(max_workers=max(1, args.jobs)) as pool:
        for i, path, out, rc, err, secs in pool.map(job, range(len(cases))):
            kind, sample, tag, data = cases[i]
            if secs > slowest[0]:
                slowest = (secs, "%s (%s %s %s)" % (os.path.basename(path), kind, sample, tag))
            if rc is None:
                label = "timeout"
            elif rc < 0:
                label = "signal %s" % signal.Signals(-rc).name
            else:
                label = "exit %d" % rc
            sanitizer = any(m in err for m in SANITIZER_MARKERS)
            if sanitizer:
                label += " + sanitizer report"
            codes[label] += 1
            by_kind[kind.split("+")[0]][label] += 1
            problem = None
            if rc is None or rc < 0 or sanitizer or rc not in DOCUMENTED_EXIT_CODES:
                problem = label
            elif kind == "base" and rc != 0:
                problem = "base file failed: " + err.decode("utf-8", "replace").strip()
            elif rc != 0:
                lines = err.decode("utf-8", "replace").strip().splitlines()
                if len(lines) != 1 or not lines[0].startswith("nvv: "):
                    problem = "exit %d without a one-line 'nvv: ' message: %r" % (rc, err[:300])
                elif rc == 3 and not lines[0].startswith("nvv: " + path + ": "):
                    problem = "exit 3 message does not name the file: %r" % lines[0][:300]
            if problem:
                os.makedirs(keep_dir, exist_ok=True)
                kept = os.path.join(keep_dir, os.path.basename(path))
                shutil.copyfile(path, kept)
                problems.append("%s [%s, %s %s]: %s" % (kept, kind, sample, tag, problem))
            for p in (path, out):
                if os.path.exists(p):
                    os.unlink(p)
            done = i + 1
            if done % 250 == 0:
                print("  %d/%d files, %.0f s" % (done, len(cases), time.time() - start), flush=True)

    print("\nfiles run: %d (%d base + %d mutants) in %.0f s; slowest %.2f s: %s"
          % (len(cases), len(bases), args.count, time.time() - start, slowest[0], slowest[1]))
    print("results:")
    for label, n in sorted(codes.items()):
        doc = ""
        if label.startswith("exit ") and label[5:].isdigit():
            doc = " (%s)" % DOCUMENTED_EXIT_CODES.get(int(label[5:]), "UNDOCUMENTED")
        print("  %-32s %6d%s" % (label, n, doc))
    signals = sum(n for l, n in codes.items() if l.startswith("signal"))
    timeouts = codes.get("timeout", 0)
    reports = sum(n for l, n in codes.items() if "sanitizer" in l)
    undocumented = sum(n for l, n in codes.items()
                       if l.startswith("exit ") and l[5:].split()[0].isdigit() and int(l[5:].split()[0]) not in DOCUMENTED_EXIT_CODES)
    print("signals: %d, timeouts: %d, sanitizer reports: %d, undocumented exit codes: %d" % (signals, timeouts, reports, undocumented))
    print("by first mutation:")
    for kind in sorted(by_kind):
        print("  %-12s %s" % (kind, ", ".join("%s: %d" % kv for kv in sorted(by_kind[kind].items()))))
    if problems:
        print("\nPROBLEMS (%d):" % len(problems))
        for p in problems[:50]:
            print("  " + p)
    if not args.workdir and not problems:
        shutil.rmtree(work, ignore_errors=True)
    return 1 if problems else 0


if __name__ == "__main__":
    sys.exit(main())
