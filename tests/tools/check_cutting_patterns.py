#!/usr/bin/python3
"""Independent checks of export-dxf's output, for the tests (run with Debian's /usr/bin/python3,
which has python3-ezdxf). Exits 0 when every check passes, else prints each failure and exits 1.

  check_cutting_patterns.py dxf DXF GARMENT_OBJ ALLOWANCE_MM [--strict] [--merged]
  check_cutting_patterns.py svg SVG GARMENT_OBJ ALLOWANCE_MM
  check_cutting_patterns.py seams REPORT_JSON TOLERANCE_MM MIN_SEAMS

The garment OBJ is parsed here, without our code: vt are the patterns [m], one g per panel.
"""
import json
import math
import os
import re
import struct
import subprocess
import sys
import tempfile
import xml.etree.ElementTree as ET

TOL = 0.01  # mm
MITRE_REACH = math.sqrt(2.0 ** 2 + 1.0)  # farthest cut vertex, in allowances (squared corner, mitre limit 2)
LAYERS = {"1", "2", "3", "4", "6", "7", "8", "11", "13", "14", "15"}
PIECE_TEXTS = ["Piece Name:", "Size:", "Quantity:", "Category:", "Annotation:", "Material:"]
STYLE_TEXTS = ["Style Name:", "Creation Date:", "Author:", "Sample Size:", "Units: METRIC"]
failures = []


def fail(message):
    failures.append(message)


def read_obj_panels(path):
    """Panel name -> list of boundary loops of the pattern, as lists of (x, y) in mm.

    Panels are the `g`/`o` groups; a file without groups (ARCSim / Berkeley Garment Library) has
    one panel per connected piece of pattern, named panel-1, panel-2... in the order of their
    first face, its per-corner vt merged where a (v, vt) pair repeats."""
    vts, faces, group, order = [], {}, None, []
    with open(path) as f:
        for line in f:
            parts = line.split()
            if not parts:
                continue
            if parts[0] == "vt":
                vts.append((float(parts[1]) * 1000.0, float(parts[2]) * 1000.0))
            elif parts[0] in ("g", "o"):
                group = " ".join(parts[1:])
                if group not in faces:
                    faces[group] = []
                    order.append(group)
            elif parts[0] == "f":
                corners = [(int(p.split("/")[0]) - 1, int(p.split("/")[1]) - 1) for p in parts[1:]]
                for k in range(1, len(corners) - 1):
                    faces.setdefault(group, []).append([corners[0], corners[k], corners[k + 1]])
                if group is None and None not in order:
                    order.append(None)
    if order == [None]:
        # Merge vt by (v, position); split into connected pieces.
        key_id, remap = {}, []
        tris = []
        for tri in faces[None]:
            ids = []
            for v, t in tri:
                key = (v, vts[t])
                if key not in key_id:
                    key_id[key] = len(key_id)
                    remap.append(vts[t])
                ids.append(key_id[key])
            tris.append(ids)
        parent = list(range(len(remap)))

        def find(x):
            while parent[x] != x:
                parent[x] = parent[parent[x]]
                x = parent[x]
            return x
        for a, b, c in tris:
            for y in (b, c):
                ra, ry = find(a), find(y)
                if ra != ry:
                    parent[ry] = ra
        comp, grouped = {}, {}
        for tri in tris:
            r = find(tri[0])
            if r not in comp:
                comp[r] = f"panel-{len(comp) + 1}"
                grouped[comp[r]] = []
            grouped[comp[r]].append(tri)
        vts, order, faces = remap, list(grouped), grouped
    else:
        faces = {g: [[t for _, t in tri] for tri in tris] for g, tris in faces.items()}
    panels = {}
    for name in order:
        count = {}
        for tri in faces[name]:
            for k in range(3):
                a, b = tri[k], tri[(k + 1) % 3]
                count[(min(a, b), max(a, b))] = count.get((min(a, b), max(a, b)), 0) + 1
        nxt = {}
        for tri in faces[name]:
            for k in range(3):
                a, b = tri[k], tri[(k + 1) % 3]
                if count[(min(a, b), max(a, b))] == 1:
                    nxt[a] = b
        loops, seen = [], set()
        for start in nxt:
            if start in seen:
                continue
            loop, v = [], start
            while v not in seen:
                seen.add(v)
                loop.append(vts[v])
                v = nxt[v]
            loops.append(loop)
        panels[name] = loops
    return panels


def block_names(panels):
    """Panel name -> block name: upper-case ASCII letters, digits, - and _, others _, unique."""
    names, used = {}, set()
    for panel in panels:
        base = "".join(c.upper() if (c.isascii() and c.isalnum()) or c in "-_" else "_" for c in panel) or "PIECE"
        name, k = base, 2
        while name in used:
            name, k = f"{base}_{k}", k + 1
        used.add(name)
        names[panel] = name
    return names


def seg_dist(p, a, b):
    ax, ay = b[0] - a[0], b[1] - a[1]
    l2 = ax * ax + ay * ay
    t = 0.0 if l2 == 0 else max(0.0, min(1.0, ((p[0] - a[0]) * ax + (p[1] - a[1]) * ay) / l2))
    return math.hypot(p[0] - a[0] - t * ax, p[1] - a[1] - t * ay)


def loop_dist(p, loops):
    return min(seg_dist(p, l[i], l[(i + 1) % len(l)]) for l in loops for i in range(len(l)))


def inside(p, loop):
    c = False
    for i in range(len(loop)):
        a, b = loop[i], loop[(i + 1) % len(loop)]
        if (a[1] > p[1]) != (b[1] > p[1]):
            x = a[0] + (p[1] - a[1]) / (b[1] - a[1]) * (b[0] - a[0])
            if x > p[0]:
                c = not c
    return c


def orient(a, b, c):
    return (b[0] - a[0]) * (c[1] - a[1]) - (b[1] - a[1]) * (c[0] - a[0])


def crossing(a, b, c, d):
    o1, o2, o3, o4 = orient(a, b, c), orient(a, b, d), orient(c, d, a), orient(c, d, b)
    return ((o1 > 0) != (o2 > 0)) and ((o3 > 0) != (o4 > 0)) and o1 * o2 < 0 and o3 * o4 < 0


def self_intersections(loop):
    n, hits = len(loop), 0
    boxes = []
    for i in range(n):
        a, b = loop[i], loop[(i + 1) % n]
        boxes.append((min(a[0], b[0]), max(a[0], b[0]), min(a[1], b[1]), max(a[1], b[1])))
    for i in range(n):
        for j in range(i + 2, n):
            if i == 0 and j == n - 1:
                continue
            bi, bj = boxes[i], boxes[j]
            if bi[1] < bj[0] or bj[1] < bi[0] or bi[3] < bj[2] or bj[3] < bi[2]:
                continue
            if crossing(loop[i], loop[(i + 1) % n], loop[j], loop[(j + 1) % n]):
                hits += 1
    return hits


def check_cut_line(what, cut, outline_loops, allowance):
    """cut: the cut polyline [mm]; outline_loops: the panel's boundary loops [mm]."""
    outer = max(outline_loops, key=lambda l: abs(sum(l[i][0] * l[(i + 1) % len(l)][1] - l[(i + 1) % len(l)][0] * l[i][1]
                                                     for i in range(len(l)))))
    if allowance == 0:
        if len(cut) != len(outer):
            fail(f"{what}: cut line has {len(cut)} vertices, the outline {len(outer)}")
        for p in cut:
            if min(math.hypot(p[0] - q[0], p[1] - q[1]) for q in outer) > TOL:
                fail(f"{what}: cut vertex {p} is not an outline vertex")
                break
        for q in outer:
            if min(math.hypot(p[0] - q[0], p[1] - q[1]) for p in cut) > TOL:
                fail(f"{what}: outline vertex {q} is not on the cut line")
                break
    else:
        for p in cut:
            d = loop_dist(p, outline_loops)
            if d < allowance - TOL or d > MITRE_REACH * allowance + TOL:
                fail(f"{what}: cut vertex {p} is {d:.4f} mm from the outline, allowance {allowance} mm")
                break
        for q in outer:
            if not inside(q, cut):
                fail(f"{what}: outline vertex {q} lies outside the cut line")
                break
            d = loop_dist(q, [cut])
            if d < allowance - TOL:
                fail(f"{what}: outline vertex {q} is only {d:.4f} mm inside the cut line")
                break
    hits = self_intersections(cut)
    if hits:
        fail(f"{what}: the cut line crosses itself {hits} times")


def raw_tags(path):
    with open(path, "rb") as f:
        data = f.read()
    if any(b > 0x7E or (b < 0x20 and b not in (0x0A, 0x0D, 0x09)) for b in data):
        fail(f"{path}: not plain ASCII")
    lines = data.decode("ascii", "replace").splitlines()
    return [(int(lines[i].strip()), lines[i + 1].strip()) for i in range(0, len(lines) - 1, 2)]


def check_dxf(path, obj, allowance, strict, merged=False):
    import ezdxf
    panels = read_obj_panels(obj)
    tags = raw_tags(path)
    # Version, layer table, layers used, block names: from the raw file (ezdxf adds and merges).
    version = [v for i, (c, v) in enumerate(tags) if c == 1 and i > 0 and tags[i - 1] == (9, "$ACADVER")]
    if version != ["AC1009"]:
        fail(f"$ACADVER is {version}, not AC1009 (R12)")
    table_layers, used_layers, raw_blocks = [], set(), []
    section, entity = None, None
    for i, (c, v) in enumerate(tags):
        if c == 0:
            entity = v
        elif c == 2 and entity == "SECTION":
            section = v
        elif c == 2 and section == "TABLES" and entity == "LAYER":
            table_layers.append(v)
        elif c == 2 and section == "BLOCKS" and entity == "BLOCK":
            raw_blocks.append(v)
            entity = None
        elif c == 8 and section in ("BLOCKS", "ENTITIES"):
            used_layers.add(v)
    if set(table_layers) - LAYERS - {"0"}:
        fail(f"layers outside the convention in the LAYER table: {sorted(set(table_layers) - LAYERS - {'0'})}")
    if used_layers - LAYERS:
        fail(f"entities on layers outside the convention (or on 0): {sorted(used_layers - LAYERS)}")
    upper = [b.upper() for b in raw_blocks]
    if len(set(upper)) != len(upper):
        fail(f"block names not unique: {raw_blocks}")
    if any(" " in b or not b.isascii() for b in raw_blocks):
        fail(f"block names with spaces or non-ASCII: {raw_blocks}")
    if len(raw_blocks) != len(panels) and not (merged and 0 < len(raw_blocks) < len(panels)):
        fail(f"{len(raw_blocks)} blocks for {len(panels)} panels")

    doc = ezdxf.readfile(path)  # the strict reader: raises on a malformed file
    auditor = doc.audit()
    if auditor.errors:
        fail("ezdxf audit errors: " + "; ".join(e.message for e in auditor.errors))
    # ezdxf 0.18 "fixes" the SEQEND of every POLYLINE inside a BLOCK of an R12 file, its own R12
    # output included; any other fix is a defect of ours.
    others = [e.message for e in auditor.fixes if not e.message.startswith("Deleted SEQEND")]
    if others:
        fail("ezdxf audit fixes: " + "; ".join(others))

    msp = doc.modelspace()
    inserts = [e for e in msp if e.dxftype() == "INSERT"]
    names = [e.dxf.name for e in inserts]
    for b in raw_blocks:
        if names.count(b) != 1:
            fail(f"block {b} inserted {names.count(b)} times")
    others = [e.dxftype() for e in msp if e.dxftype() != "INSERT"]
    if strict and others:
        fail(f"strict: ENTITIES holds {others}")
    if not strict:
        texts = [e.dxf.text for e in msp if e.dxftype() == "TEXT"]
        for key in STYLE_TEXTS:
            if not any(t.startswith(key) for t in texts):
                fail(f"style text '{key}' missing")
    names_of = block_names(panels)
    for panel, loops in panels.items():
        name = names_of[panel]
        if name not in doc.blocks:
            if not merged:
                fail(f"no block {name} for panel {panel}")
            continue
        block = doc.blocks[name]
        cut = [e for e in block if e.dxftype() == "POLYLINE" and e.dxf.layer == "1"]
        if len(cut) != 1 or not cut[0].is_closed:
            fail(f"block {name}: {len(cut)} polylines on layer 1, must be one closed")
            continue
        check_cut_line(f"block {name}", [(v.dxf.location[0], v.dxf.location[1]) for v in cut[0].vertices], loops, allowance)
        if allowance > 0:
            sew = [e for e in block if e.dxftype() == "POLYLINE" and e.dxf.layer == "14"]
            if len(sew) != len(loops):
                fail(f"block {name}: {len(sew)} sew lines for {len(loops)} outline loops")
            for s in sew:
                for v in s.vertices:
                    p = v.dxf.location
                    if loop_dist((p[0], p[1]), loops) > TOL:
                        fail(f"block {name}: sew-line vertex {p} is off the outline")
                        break
        texts = [e.dxf.text for e in block if e.dxftype() == "TEXT" and e.dxf.layer == "1"]
        for key in PIECE_TEXTS:
            if not any(t.startswith(key) for t in texts):
                fail(f"block {name}: piece text '{key}' missing")
        if not any(e.dxftype() == "LINE" and e.dxf.layer == "7" for e in block):
            fail(f"block {name}: no grain line on layer 7")


def parse_path(d):
    """Subpaths of an M/L/Z path as lists of (x, y)."""
    paths, current = [], None
    for cmd, args in re.findall(r"([MLZ])([^MLZ]*)", d):
        nums = [float(x) for x in re.findall(r"-?[0-9.]+(?:e-?[0-9]+)?", args)]
        if cmd == "M":
            current = [(nums[0], nums[1])]
            paths.append(current)
        elif cmd == "L":
            current.append((nums[0], nums[1]))
    return paths


def png_size(path):
    with open(path, "rb") as f:
        head = f.read(24)
    if head[:8] != b"\x89PNG\r\n\x1a\n":
        return None
    return struct.unpack(">II", head[16:24])


def check_svg(path, obj, allowance):
    panels = read_obj_panels(obj)
    ns = {"s": "http://www.w3.org/2000/svg"}
    root = ET.parse(path).getroot()  # valid XML, or this raises
    w, h = root.get("width"), root.get("height")
    if not (w.endswith("mm") and h.endswith("mm")):
        fail(f"page size {w} x {h} is not in mm")
        return
    w, h = float(w[:-2]), float(h[:-2])
    vb = [float(x) for x in root.get("viewBox").split()]
    if vb != [0.0, 0.0, w, h]:
        fail(f"viewBox {vb} does not match the page {w} x {h} mm (1 unit = 1 mm)")
    box = root.find(".//s:rect[@id='scale-box']", ns)
    if box is None or float(box.get("width")) != 100.0 or float(box.get("height")) != 50.0:
        fail("no 100 x 50 mm scale box")
    xs, ys = [float(box.get("x")), float(box.get("x")) + 100.0], [float(box.get("y")), float(box.get("y")) + 50.0]
    parent = {child: p for p in root.iter() for child in p}
    e = box
    while e is not None:
        if e.get("transform"):
            fail("the scale box is transformed: it would not print at 100 x 50 mm")
        e = parent.get(e)
    rects = []
    names_of = block_names(panels)
    for panel, loops in panels.items():
        g = root.find(f".//s:g[@id='piece-{names_of[panel]}']", ns)
        if g is None:
            fail(f"no piece group for panel {panel}")
            continue
        inner = g.find("s:g", ns)
        m = re.fullmatch(r"matrix\(1 0 0 -1 (\S+) (\S+)\)", inner.get("transform"))
        tx, ty = float(m.group(1)), float(m.group(2))
        cut = inner.find("s:path[@class='cut']", ns)
        subpaths = parse_path(cut.get("d"))
        outer = subpaths[0]
        check_cut_line(f"svg piece {panel}", outer, loops, allowance)
        page = [(x + tx, ty - y) for x, y in outer]
        xs += [p[0] for p in page]
        ys += [p[1] for p in page]
        rects.append((min(p[0] for p in page), max(p[0] for p in page), min(p[1] for p in page), max(p[1] for p in page), panel))
        if allowance > 0 and inner.find("s:path[@class='sew']", ns) is None:
            fail(f"svg piece {panel}: no sew line")
    for i in range(len(rects)):
        for j in range(i + 1, len(rects)):
            a, b = rects[i], rects[j]
            if a[0] < b[1] and b[0] < a[1] and a[2] < b[3] and b[2] < a[3]:
                fail(f"pieces {a[4]} and {b[4]} overlap on the sheet")
    margins = [min(xs), w - max(xs), min(ys), h - max(ys)]
    if any(abs(m - margins[0]) > TOL for m in margins) or margins[0] < 0:
        fail(f"the page is not the layout extent plus an even margin: margins {margins} mm")
    with tempfile.TemporaryDirectory() as tmp:
        out = os.path.join(tmp, "render.png")
        r = subprocess.run(["rsvg-convert", "--dpi-x", "96", "--dpi-y", "96", path, "-o", out], capture_output=True, text=True)
        if r.returncode != 0:
            fail(f"rsvg-convert failed: {r.stderr.strip()}")
        else:
            size = png_size(out)
            expected = (w / 25.4 * 96.0, h / 25.4 * 96.0)
            if size is None or abs(size[0] - expected[0]) > 1.0 or abs(size[1] - expected[1]) > 1.0:
                fail(f"rsvg-convert rendered {size} px, expected {expected} for 1:1 at 96 dpi")


def check_seams(report, tolerance, min_seams):
    with open(report) as f:
        data = json.load(f)
    if len(data["seams"]) < min_seams:
        fail(f"the report lists {len(data['seams'])} seams, expected at least {min_seams}")
    for s in data["seams"]:
        if abs(s["length_a_mm"] - s["length_b_mm"]) > tolerance or abs(s["difference_mm"]) > tolerance:
            fail(f"seam {s['panel_a']}-{s['panel_b']}: {s['length_a_mm']} vs {s['length_b_mm']} mm")


def main():
    kind = sys.argv[1]
    if kind == "dxf":
        check_dxf(sys.argv[2], sys.argv[3], float(sys.argv[4]), "--strict" in sys.argv[5:], "--merged" in sys.argv[5:])
    elif kind == "svg":
        check_svg(sys.argv[2], sys.argv[3], float(sys.argv[4]))
    elif kind == "seams":
        check_seams(sys.argv[2], float(sys.argv[3]), int(sys.argv[4]))
    else:
        sys.exit(f"unknown check {kind}")
    for f in failures:
        print("FAIL:", f)
    print("ok" if not failures else f"{len(failures)} failures")
    sys.exit(1 if failures else 0)


if __name__ == "__main__":
    main()
