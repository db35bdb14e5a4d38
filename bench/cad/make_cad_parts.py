#!/usr/bin/python3
"""Machined parts made by a real CAD kernel (gmsh's OpenCASCADE), meshed as CAD exporters mesh
them, with their sharp-feature truth taken from the CAD model. Input of the accuracy
benchmark's "cad" section (bench/cad_parts.cpp).

Usage: make_cad_parts.py OUTDIR [PART_SIZE ...]
Writes, for every part and mesh size (or only those named, e.g. block_default), OUTDIR/<part>_<size>.obj and OUTDIR/<part>_<size>.truth,
and OUTDIR/parts.txt (one "<part>_<size>" per line, in the order the benchmark reports them).
Needs Debian bookworm's python3-gmsh (gmsh 4.8.4 with OpenCASCADE 7.6); deterministic for a
given gmsh build (one meshing thread).

The parts (millimetres):
  block        40x30x20 block: 4 mm fillets on its vertical edges, 45 deg chamfers of 2 mm on
               its top edges, a 5 mm radius through hole;
  shallow      a slab whose top is chamfered at 20 deg and 30 deg (two-distance chamfers) and
               a 12 deg ramp: creases of 12..30 deg on top, 60..78 deg below them;
  draft_boss   a plate with a round boss and a square boss, both with 8 deg draft, a 2 mm
               fillet where the round boss meets the plate (tangent, not a crease);
  ribs         a plate with three 1.5 mm thin ribs 10 mm high (pairs of 90 deg creases 1.5 mm
               apart, concave creases at their feet), 0.7 mm fillets on one rib's top edges;
  bracket      an L-bracket: 6 mm inner fillet (tangent), two holes with 45 deg countersinks,
               a 30 deg chamfer on the flange's outer edge.
Mesh sizes:
  export   as STL exporters write them: every curve split into as few segments as turn by at
           most 30 deg each (straight edges: one segment), faces with (nearly) no nodes of
           their own: long slivers, fans around holes; Delaunay;
  coarse   no size bound, element size from the curvature of curves and faces (12 points per
           turn): planar faces carry only their boundary nodes, curved ones a few rows; Delaunay;
  default  element size bounded by the bounding-box diagonal / 20, 16 points per turn;
  fine     diagonal / 50, 24 points per turn.

Truth (the .truth file, text, vertex ids 0-based in the OBJ's order):
  nvv-cad-truth 1
  gmsh <version>
  part <part> size <size>
  vertices N
  N lines: sharp dim entity known nx ny nz k1 k2
     sharp   1 if the node lies on a sharp model curve (or is a model vertex ending one)
     dim, entity   gmsh's classification of the node (0 point, 1 curve, 2 surface)
     known   1 where the outward normal and the principal curvatures are defined (nodes
             inside a face, dim 2); then n = outward unit normal, k1 >= k2 the principal
             curvatures, positive where the surface bends away from the outward normal
             (a convex cylinder of radius r: k1 = 1/r, k2 = 0)
  edges M
  M lines: a b angle convex   mesh edges on sharp curves; angle = the curve's dihedral
             normal-angle (deg, between the two faces' outward normals), convex 1 / -1
  curves C
  C lines: tag angle_median angle_min angle_max convex sharp nodes    every model curve
             between two distinct faces (seams of periodic faces have one face: left out)
A curve is sharp when its median normal-angle (sampled at 21 points along it) is at least
SHARP_DEG; tangent fillet and blend boundaries measure 0 and are not sharp.
"""
import math
import os
import sys

import gmsh

SHARP_DEG = 5.0
SIZES = [
    # name, size bound as a fraction of the bounding-box diagonal (0: none), points per 2 pi,
    # algorithm; "export" alone splits curves by their turning and gives faces no nodes
    ("export", 0.0, 12, 5),
    ("coarse", 0.0, 12, 5),
    ("default", 1 / 20, 16, 6),
    ("fine", 1 / 50, 24, 6),
]

occ = None


def curves_where(pred):
    """Model curves whose bounding box satisfies pred(xmin, ymin, zmin, xmax, ymax, zmax)."""
    return [t for (d, t) in gmsh.model.occ.getEntities(1) if pred(*gmsh.model.occ.getBoundingBox(1, t))]


def near(a, b, eps=1e-6):
    return abs(a - b) < eps


def part_block():
    v = occ.addBox(0, 0, 0, 40, 30, 20)
    occ.synchronize()
    vertical = curves_where(lambda x0, y0, z0, x1, y1, z1: near(z0, 0) and near(z1, 20) and near(x0, x1))
    occ.fillet([v], vertical, [4])
    occ.synchronize()
    vol = occ.getEntities(3)[0][1]
    # the top rim: every curve lying in z = 20
    top = curves_where(lambda x0, y0, z0, x1, y1, z1: near(z0, 20) and near(z1, 20))
    top_face = [t for (d, t) in occ.getEntities(2)
                if all(near(c, 20) for c in (occ.getBoundingBox(2, t)[2], occ.getBoundingBox(2, t)[5]))]
    occ.chamfer([vol], top, top_face * len(top), [2])
    occ.synchronize()
    vol = occ.getEntities(3)[0][1]
    hole = occ.addCylinder(20, 15, -1, 0, 0, 22, 5)
    occ.cut([(3, vol)], [(3, hole)])


def part_shallow():
    # Slab 50 x 30 x 14; its top-front edge chamfered so the chamfer face is 20 deg off the top
    # (distances 8 on the top, 8 tan 20 on the front), the top-back edge 30 deg off the top.
    v = occ.addBox(0, 0, 0, 50, 30, 14)
    occ.synchronize()

    def edge_at(y, z):
        return curves_where(lambda x0, y0, z0, x1, y1, z1: near(y0, y) and near(y1, y) and near(z0, z) and near(z1, z))

    top = [t for (d, t) in occ.getEntities(2) if near(occ.getBoundingBox(2, t)[2], 14) and near(occ.getBoundingBox(2, t)[5], 14)][0]
    front, back = edge_at(0, 14), edge_at(30, 14)
    occ.chamfer([v], front + back, [top, top],
                [8, 8 * math.tan(math.radians(20)), 8, 8 * math.tan(math.radians(30))])
    occ.synchronize()
    vol = occ.getEntities(3)[0][1]
    # A 12 deg ramp cut into the right end: a wedge removed from x = 38..50 on the top.
    p = [occ.addPoint(38, -1, 14.001), occ.addPoint(51, -1, 14.001 - 13 * math.tan(math.radians(12))),
         occ.addPoint(51, -1, 20), occ.addPoint(38, -1, 20)]
    lines = [occ.addLine(p[i], p[(i + 1) % 4]) for i in range(4)]
    s = occ.addPlaneSurface([occ.addCurveLoop(lines)])
    wedge = occ.extrude([(2, s)], 0, 32, 0)
    wv = [dt for dt in wedge if dt[0] == 3]
    occ.cut([(3, vol)], wv)


def drafted_box(x, y, z0, w, d, h, draft_deg):
    t = h * math.tan(math.radians(draft_deg))
    def rect(zz, inset):
        pts = [occ.addPoint(x + inset, y + inset, zz), occ.addPoint(x + w - inset, y + inset, zz),
               occ.addPoint(x + w - inset, y + d - inset, zz), occ.addPoint(x + inset, y + d - inset, zz)]
        return occ.addCurveLoop([occ.addLine(pts[i], pts[(i + 1) % 4]) for i in range(4)])
    return occ.addThruSections([rect(z0, 0), rect(z0 + h, t)], makeSolid=True, makeRuled=True)


def part_draft_boss():
    plate = occ.addBox(0, 0, 0, 60, 40, 8)
    t = 12 * math.tan(math.radians(8))
    boss = occ.addCone(18, 20, 7.99, 0, 0, 12.01, 9, 9 - t)
    sq = drafted_box(36, 11, 7.99, 18, 18, 12.01, 8)
    out, _ = occ.fuse([(3, plate)], [(3, boss)] + sq)
    occ.synchronize()
    vol = out[0][1]
    # the round boss's foot: the circle of radius 9 at z = 8
    foot = curves_where(lambda x0, y0, z0, x1, y1, z1: near(z0, 8, 1e-3) and near(z1, 8, 1e-3)
                        and near(x0, 9, 1e-2) and near(x1, 27, 1e-2))
    occ.fillet([vol], foot, [2])


def part_ribs():
    plate = occ.addBox(0, 0, 0, 60, 40, 4)
    ribs = [(3, occ.addBox(8 + 20 * i, 4, 3.99, 1.5, 32, 10.01)) for i in range(3)]
    out, _ = occ.fuse([(3, plate)], ribs)
    occ.synchronize()
    vol = out[0][1]
    # round the top of the last rib (two edges along y at z = 14, x in [48, 49.5])
    top = curves_where(lambda x0, y0, z0, x1, y1, z1: near(z0, 14) and near(z1, 14) and x0 > 47 and near(x0, x1))
    occ.fillet([vol], top, [0.7])


def part_bracket():
    # L profile in the xz plane, extruded 30 along y: foot 50 x 6, upright 6 x 40.
    pts = [(0, 0), (50, 0), (50, 6), (6, 6), (6, 40), (0, 40)]
    p = [occ.addPoint(x, 0, z) for (x, z) in pts]
    lines = [occ.addLine(p[i], p[(i + 1) % len(p)]) for i in range(len(p))]
    s = occ.addPlaneSurface([occ.addCurveLoop(lines)])
    ext = occ.extrude([(2, s)], 0, 30, 0)
    vol = [dt for dt in ext if dt[0] == 3][0][1]
    occ.synchronize()
    inner = curves_where(lambda x0, y0, z0, x1, y1, z1: near(x0, 6) and near(x1, 6) and near(z0, 6) and near(z1, 6))
    occ.fillet([vol], inner, [6])
    occ.synchronize()
    vol = occ.getEntities(3)[0][1]
    # the foot's outer top edge (x = 50, z = 6) chamfered 30 deg off the top face
    top = [t for (d, t) in occ.getEntities(2)
           if near(occ.getBoundingBox(2, t)[2], 6) and near(occ.getBoundingBox(2, t)[5], 6)]
    edge = curves_where(lambda x0, y0, z0, x1, y1, z1: near(x0, 50) and near(x1, 50) and near(z0, 6) and near(z1, 6))
    occ.chamfer([vol], edge, top, [6, 6 * math.tan(math.radians(30))])
    occ.synchronize()
    vol = occ.getEntities(3)[0][1]
    # two holes through the foot with 45 deg countersinks (cone 9 -> 4 over 5 mm, then 4 mm bore)
    tools = []
    for y in (9, 21):
        tools.append((3, occ.addCylinder(28, y, -1, 0, 0, 8, 3)))
        tools.append((3, occ.addCone(28, y, 3, 0, 0, 3.01, 3, 6.01)))
    occ.cut([(3, vol)], tools)


PARTS = [("block", part_block), ("shallow", part_shallow), ("draft_boss", part_draft_boss),
         ("ribs", part_ribs), ("bracket", part_bracket)]


def unit(v):
    n = math.sqrt(sum(c * c for c in v))
    return [c / n for c in v] if n > 0 else [0.0, 0.0, 0.0]


def angle_deg(a, b):
    d = max(-1.0, min(1.0, sum(x * y for x, y in zip(unit(a), unit(b)))))
    return math.degrees(math.acos(d))


def natural_normal(s, uv):
    """Unit du x dv of face s's underlying surface at uv (finite differences): the normal that
    OpenCASCADE signs its curvatures against, whatever the face's orientation in the solid."""
    (u0, v0), (u1, v1) = gmsh.model.getParametrizationBounds(2, s)
    hu, hv = 1e-6 * (u1 - u0), 1e-6 * (v1 - v0)
    du = hu if uv[0] + hu <= u1 else -hu
    dv = hv if uv[1] + hv <= v1 else -hv
    p = gmsh.model.getValue(2, s, uv)
    pu = gmsh.model.getValue(2, s, [uv[0] + du, uv[1]])
    pv = gmsh.model.getValue(2, s, [uv[0], uv[1] + dv])
    a = [(pu[k] - p[k]) / du for k in range(3)]
    b = [(pv[k] - p[k]) / dv for k in range(3)]
    return unit([a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]])


def principal_curvatures(s, uv, outward, ksign):
    """k1 >= k2 of face s at uv in this benchmark's convention (positive where the face bends
    away from its outward normal `outward`)."""
    kmax, kmin, _, _ = gmsh.model.getPrincipalCurvatures(s, uv)
    r = 1 if sum(x * y for x, y in zip(natural_normal(s, uv), outward)) > 0 else -1
    a, b = ksign * r * kmax[0], ksign * r * kmin[0]
    return max(a, b), min(a, b)


def turning(c):
    """How far curve c's tangent turns along it (radians), from 65 samples."""
    (t0,), (t1,) = gmsh.model.getParametrizationBounds(1, c)
    ts = [t0 + (t1 - t0) * i / 64 for i in range(65)]
    tang = [unit(gmsh.model.getDerivative(1, c, [t])) for t in ts]
    return sum(math.radians(angle_deg(a, b)) for a, b in zip(tang, tang[1:]))


def curvature_sign():
    """+1 or -1: the factor that turns OpenCASCADE's principal curvatures, signed against the
    underlying surface's du x dv, into this benchmark's convention, calibrated on a sphere."""
    gmsh.model.add("calib")
    gmsh.model.occ.addSphere(0, 0, 0, 2)
    gmsh.model.occ.synchronize()
    s = abs(gmsh.model.getBoundary(gmsh.model.getEntities(3), oriented=True)[0][1])
    uv = [0.3, 0.4]
    p = gmsh.model.getValue(2, s, uv)
    k1, k2 = principal_curvatures(s, uv, unit(p), 1)
    gmsh.clear()
    return 1 if k1 + k2 > 0 else -1


def mesh_part(name, build, size, out_dir, ksign, version):
    sname, frac, per_turn, algo = size
    gmsh.model.add(name + "_" + sname)
    global occ
    occ = gmsh.model.occ
    build()
    occ.synchronize()
    vols = gmsh.model.getEntities(3)
    assert len(vols) == 1, (name, vols)
    xmin, ymin, zmin, xmax, ymax, zmax = gmsh.model.getBoundingBox(-1, -1)
    diag = math.sqrt((xmax - xmin) ** 2 + (ymax - ymin) ** 2 + (zmax - zmin) ** 2)
    gmsh.option.setNumber("Mesh.MeshSizeMax", diag * frac if frac > 0 else 1e22)
    gmsh.option.setNumber("Mesh.MeshSizeMin", 0)
    export = sname == "export"
    gmsh.option.setNumber("Mesh.MeshSizeFromCurvature", 0 if export else per_turn)
    gmsh.option.setNumber("Mesh.MeshSizeExtendFromBoundary", 1 if frac > 0 else 0)
    if export:
        # As an exporter's angular tolerance: each curve split into as few segments as turn by
        # at most 360 / per_turn degrees each (a straight line: one segment); faces then get
        # no nodes of their own.
        for (d, c) in gmsh.model.getEntities(1):
            gmsh.model.mesh.setTransfiniteCurve(c, 1 + max(1, math.ceil(turning(c) * per_turn / (2 * math.pi) - 1e-6)))
    gmsh.option.setNumber("Mesh.MeshSizeFromPoints", 0)
    gmsh.option.setNumber("Mesh.Algorithm", algo)
    gmsh.option.setNumber("Mesh.RandomSeed", 1)
    gmsh.model.mesh.generate(2)

    # outward orientation of each face in the solid
    fsign = {abs(t): (1 if t > 0 else -1) for (d, t) in gmsh.model.getBoundary(vols, oriented=True)}
    tags, coords, _ = gmsh.model.mesh.getNodes()
    xyz = {int(t): (coords[3 * i], coords[3 * i + 1], coords[3 * i + 2]) for i, t in enumerate(tags)}
    tris = []
    for (d, s) in gmsh.model.getEntities(2):
        etypes, _, enodes = gmsh.model.mesh.getElements(2, s)
        for et, nodes in zip(etypes, enodes):
            assert et == 2, et  # 3-node triangles
            for i in range(0, len(nodes), 3):
                a, b, c = int(nodes[i]), int(nodes[i + 1]), int(nodes[i + 2])
                tris.append((a, b, c) if fsign.get(s, 1) > 0 else (a, c, b))
    used = sorted({n for t in tris for n in t})
    idx = {n: i for i, n in enumerate(used)}
    # every directed edge once: a closed, consistently oriented 2-manifold
    directed = {}
    for t in tris:
        for j in range(3):
            e = (t[j], t[(j + 1) % 3])
            assert e not in directed, (name, sname, "edge used twice in one direction")
            directed[e] = 1
    assert all((b, a) in directed for (a, b) in directed), (name, sname, "open or inconsistent")

    # node classification
    ndim, ntag, nuv = {}, {}, {}
    for dim in (0, 1, 2):
        for (d, t) in gmsh.model.getEntities(dim):
            nt, _, pc = gmsh.model.mesh.getNodes(dim, t, includeBoundary=False, returnParametricCoord=True)
            for i, n in enumerate(nt):
                ndim[int(n)], ntag[int(n)] = dim, t
                if dim == 2:
                    nuv[int(n)] = (pc[2 * i], pc[2 * i + 1])

    # curves: dihedral normal-angle from the faces' outward normals along the curve
    curve_rows, sharp_curves = [], {}
    for (d, c) in gmsh.model.getEntities(1):
        up, _ = gmsh.model.getAdjacencies(1, c)
        faces = sorted(set(int(f) for f in up))
        if len(faces) != 2:
            continue
        t0, t1 = gmsh.model.getParametrizationBounds(1, c)
        angles = []
        for i in range(21):
            t = t0[0] + (t1[0] - t0[0]) * (0.02 + 0.96 * i / 20)
            p = gmsh.model.getValue(1, c, [t])
            ns = []
            for f in faces:
                uv = gmsh.model.getParametrization(2, f, p)
                n = gmsh.model.getNormal(f, list(uv))
                ns.append([fsign.get(f, 1) * x for x in n])
            angles.append(angle_deg(ns[0], ns[1]))
        angles.sort()
        med = angles[len(angles) // 2]
        sharp = med >= SHARP_DEG
        curve_rows.append([c, med, angles[0], angles[-1], 0, int(sharp), 0])
        if sharp:
            sharp_curves[c] = len(curve_rows) - 1

    # feature edges: the mesh's 1-D elements on sharp curves; convexity from the triangles
    opp = {}
    for t in tris:
        for j in range(3):
            opp[(t[j], t[(j + 1) % 3])] = t[(j + 2) % 3]
    edges, sharp_nodes = [], set()
    for c, row in sharp_curves.items():
        etypes, _, enodes = gmsh.model.mesh.getElements(1, c)
        vote = 0
        for et, nodes in zip(etypes, enodes):
            for i in range(0, len(nodes), 2):
                a, b = int(nodes[i]), int(nodes[i + 1])
                sharp_nodes.update((a, b))
                edges.append([a, b, c])
                # convex when the far vertex of the other triangle lies below this triangle's plane
                if (a, b) in opp and (b, a) in opp:
                    pa, pb, pc_, pd = xyz[a], xyz[b], xyz[opp[(a, b)]], xyz[opp[(b, a)]]
                    u = [pb[k] - pa[k] for k in range(3)]
                    w = [pc_[k] - pa[k] for k in range(3)]
                    n = [u[1] * w[2] - u[2] * w[1], u[2] * w[0] - u[0] * w[2], u[0] * w[1] - u[1] * w[0]]
                    vote += 1 if sum(n[k] * (pd[k] - pa[k]) for k in range(3)) < 0 else -1
        curve_rows[row][4] = 1 if vote > 0 else -1
        curve_rows[row][6] = len(set(x for e in edges if e[2] == c for x in e[:2]))

    base = os.path.join(out_dir, name + "_" + sname)
    with open(base + ".obj", "w") as f:
        f.write("# %s, %s mesh, gmsh %s (OpenCASCADE)\n" % (name, sname, version))
        for n in used:
            f.write("v %.9g %.9g %.9g\n" % xyz[n])
        for t in tris:
            f.write("f %d %d %d\n" % (idx[t[0]] + 1, idx[t[1]] + 1, idx[t[2]] + 1))
    with open(base + ".truth", "w") as f:
        f.write("nvv-cad-truth 1\ngmsh %s\npart %s size %s\nvertices %d\n" % (version, name, sname, len(used)))
        for n in used:
            known, nv, k1, k2 = 0, (0.0, 0.0, 0.0), 0.0, 0.0
            if ndim.get(n) == 2:
                s = ntag[n]
                uv = list(nuv[n])
                nv = unit(gmsh.model.getNormal(s, uv))  # gmsh orients it as the face in its solid
                nv = nv if fsign.get(s, 1) > 0 else [-x for x in nv]
                k1, k2 = principal_curvatures(s, uv, nv, ksign)
                known = 1
            f.write("%d %d %d %d %.9g %.9g %.9g %.9g %.9g\n" % (
                int(n in sharp_nodes), ndim.get(n, -1), ntag.get(n, -1), known, nv[0], nv[1], nv[2], k1, k2))
        f.write("edges %d\n" % len(edges))
        for a, b, c in edges:
            r = curve_rows[sharp_curves[c]]
            f.write("%d %d %.4f %d\n" % (idx[a], idx[b], r[1], r[4]))
        f.write("curves %d\n" % len(curve_rows))
        for r in curve_rows:
            f.write("%d %.4f %.4f %.4f %d %d %d\n" % tuple(r))
    nsharp = sum(r[5] for r in curve_rows)
    angles = sorted(set(round(r[1]) for r in curve_rows if r[5]))
    print("%-18s %6d vertices %6d triangles, %2d sharp curves of %2d (angles %s)" % (
        name + "_" + sname, len(used), len(tris), nsharp, len(curve_rows), angles))
    gmsh.clear()


def main():
    known = [name + "_" + size[0] for name, _ in PARTS for size in SIZES]
    if len(sys.argv) < 2 or any(a not in known for a in sys.argv[2:]):
        print(next(l for l in __doc__.split("\n") if l.startswith("Usage")), file=sys.stderr)
        print("PART_SIZE: one of " + " ".join(known), file=sys.stderr)
        return 2
    out_dir, only = sys.argv[1], set(sys.argv[2:])
    os.makedirs(out_dir, exist_ok=True)
    gmsh.initialize(["make_cad_parts"], readConfigFiles=False)
    gmsh.option.setNumber("General.Terminal", 0)
    gmsh.option.setNumber("General.NumThreads", 1)
    version = gmsh.option.getString("General.Version")
    ksign = curvature_sign()
    names = []
    for name, build in PARTS:
        for size in SIZES:
            if only and name + "_" + size[0] not in only:
                continue
            mesh_part(name, build, size, out_dir, ksign, version)
            names.append(name + "_" + size[0])
    with open(os.path.join(out_dir, "parts.txt"), "w") as f:
        f.write("".join(n + "\n" for n in names))
    print("gmsh %s, curvature sign %+d, %d meshes in %s" % (version, ksign, len(names), out_dir))
    gmsh.finalize()
    return 0


if __name__ == "__main__":
    sys.exit(main())
