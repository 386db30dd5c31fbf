"""Damage to a gmsh .msh file (ASCII, format 2.2 or 4.1) that chute must refuse on import: an
element with a repeated node, of zero size or area (a node moved onto another or between two),
a quadrangle made a bow-tie or non-convex, an element turned over against its neighbours, an
element repeated, two groups of one dimension with one name, a start view that leaves out a
node. damage(text, kind, rng) returns the damaged text and a description, or None when the mesh
has nothing to damage that way (no quadrangle, no view, fewer than two groups of a dimension).
Binary twins are made by gmsh from the damaged ASCII file (tests/attack/inputs.py)."""

import re

KINDS = ["repeated_node", "coincident_nodes", "collinear_nodes", "bowtie", "reflex_quad",
         "turned_over", "repeated_element", "group_name", "view_missing_node"]
DIM = {15: 0, 1: 1, 2: 2, 3: 2}


class Msh:
    """The lines of an ASCII .msh, with where its nodes, elements and names are."""

    def __init__(self, text):
        self.lines = text.split("\n")
        self.v4 = self.lines[1].split()[0].startswith("4")
        self.nodes = {}     # tag -> (line index, coordinates)
        self.elements = []  # (line index, gmsh type, [node tags], its 4.1 block's header line)
        self.names = []     # (line index, dim, tag, name)
        self.view = None    # (count line index, first value line index, count)
        i = 0
        n = len(self.lines)
        while i < n:
            head = self.lines[i].strip()
            if head == "$PhysicalNames":
                k = int(self.lines[i + 1])
                for j in range(i + 2, i + 2 + k):
                    dim, tag, name = self.lines[j].split(None, 2)
                    self.names.append((j, int(dim), int(tag), name.strip().strip('"')))
                i += 2 + k
            elif head == "$Nodes":
                i = self._nodes(i)
            elif head == "$Elements":
                i = self._elements(i)
            elif head == "$NodeData" and self.view is None:
                j = i + 1
                j += 1 + int(self.lines[j])      # string tags
                j += 1 + int(self.lines[j])      # real tags
                k = int(self.lines[j])           # integer tags: step, components, count, ...
                count = int(self.lines[j + 3])
                self.view = (j + 3, j + 1 + k, count)
                i = j + 1 + k + count
            else:
                i += 1

    def _nodes(self, i):
        if not self.v4:
            k = int(self.lines[i + 1])
            for j in range(i + 2, i + 2 + k):
                p = self.lines[j].split()
                self.nodes[int(p[0])] = (j, [float(x) for x in p[1:4]])
            return i + 2 + k
        blocks = int(self.lines[i + 1].split()[0])
        j = i + 2
        for _ in range(blocks):
            dim, ent, param, m = map(int, self.lines[j].split())
            tags = [int(self.lines[j + 1 + q]) for q in range(m)]
            for q, t in enumerate(tags):
                line = j + 1 + m + q
                self.nodes[t] = (line, [float(x) for x in self.lines[line].split()[:3]])
            j += 1 + 2 * m
        return j

    def _elements(self, i):
        if not self.v4:
            k = int(self.lines[i + 1])
            for j in range(i + 2, i + 2 + k):
                p = list(map(int, self.lines[j].split()))
                self.elements.append((j, p[1], p[3 + p[2]:], None))
            return i + 2 + k
        blocks = int(self.lines[i + 1].split()[0])
        j = i + 2
        for _ in range(blocks):
            dim, ent, typ, m = map(int, self.lines[j].split())
            for q in range(m):
                p = list(map(int, self.lines[j + 1 + q].split()))
                self.elements.append((j + 1 + q, typ, p[1:], j))
            j += 1 + m
        return j

    def set_nodes(self, element, nodes):
        line, typ, old, _ = element
        p = self.lines[line].split()
        keep = len(p) - len(old)
        self.lines[line] = " ".join(p[:keep] + [str(t) for t in nodes])

    def move(self, tag, x):
        line, _ = self.nodes[tag]
        p = self.lines[line].split()
        coords = " ".join(repr(v) for v in x)
        self.lines[line] = coords if self.v4 else p[0] + " " + coords

    def text(self):
        return "\n".join(self.lines)


def _bump_count(lines, header_index, v4, by_block_line=None):
    """An element repeated: the counts of $Elements (and of its 4.1 block) grow by one."""
    p = lines[header_index + 1].split()
    if v4:
        p[1] = str(int(p[1]) + 1)
        p[3] = str(int(p[3]) + 1)
        b = lines[by_block_line].split()
        b[3] = str(int(b[3]) + 1)
        lines[by_block_line] = " ".join(b)
    else:
        p[0] = str(int(p[0]) + 1)
    lines[header_index + 1] = " ".join(p)


def damage(text, kind, rng):
    m = Msh(text)
    surface = [e for e in m.elements if DIM.get(e[1]) == 2]
    quads = [e for e in surface if e[1] == 3]
    lines = [e for e in m.elements if DIM.get(e[1]) == 1]
    if kind == "repeated_node":
        e = rng.choice(surface + lines)
        nodes = list(e[2])
        nodes[1] = nodes[0]
        m.set_nodes(e, nodes)
        return m.text(), "element on line %d: node %d twice" % (e[0] + 1, nodes[0])
    if kind == "coincident_nodes":
        e = rng.choice(surface + lines)
        a, b = e[2][0], e[2][1]
        m.move(b, m.nodes[a][1])
        return m.text(), "node %d moved onto node %d" % (b, a)
    if kind == "collinear_nodes":
        e = rng.choice(surface)
        a, b, c = e[2][0], e[2][1], e[2][2]
        xa, xc = m.nodes[a][1], m.nodes[c][1]
        m.move(b, [(xa[k] + xc[k]) / 2 for k in range(3)])
        return m.text(), "node %d moved between nodes %d and %d" % (b, a, c)
    if kind == "bowtie":
        if not quads:
            return None
        e = rng.choice(quads)
        n = list(e[2])
        n[1], n[2] = n[2], n[1]
        m.set_nodes(e, n)
        return m.text(), "quadrangle on line %d made a bow-tie" % (e[0] + 1)
    if kind == "reflex_quad":
        if not quads:
            return None
        e = rng.choice(quads)
        n = e[2]
        # Node 1 pulled past the diagonal 0-2: a dart.
        x0, x1, x2 = m.nodes[n[0]][1], m.nodes[n[1]][1], m.nodes[n[2]][1]
        mid = [(x0[k] + x2[k]) / 2 for k in range(3)]
        m.move(n[1], [mid[k] + 0.5 * (mid[k] - x1[k]) for k in range(3)])
        return m.text(), "quadrangle on line %d made non-convex" % (e[0] + 1)
    if kind == "turned_over":
        e = rng.choice(surface)
        m.set_nodes(e, list(reversed(e[2])))
        return m.text(), "element on line %d turned over" % (e[0] + 1)
    if kind == "repeated_element":
        # A second element on the same nodes (a new tag, its nodes rotated): gmsh keeps it when
        # it saves the file (an identical line, tag included, it drops).
        e = rng.choice(surface + lines)
        _bump_count(m.lines, m.lines.index("$Elements"), m.v4, e[3])
        p = m.lines[e[0]].split()
        nodes = p[len(p) - len(e[2]):]
        p[0] = str(10 ** 7 + e[0])
        p[len(p) - len(nodes):] = nodes[1:] + nodes[:1]
        m.lines.insert(e[0] + 1, " ".join(p))
        return m.text(), "element on line %d repeated" % (e[0] + 1)
    if kind == "group_name":
        by_dim = {}
        for n in m.names:
            by_dim.setdefault(n[1], []).append(n)
        pairs = [g for g in by_dim.values() if len(g) >= 2]
        if not pairs:
            return None
        a, b = rng.sample(rng.choice(pairs), 2)
        m.lines[b[0]] = '%d %d "%s"' % (b[1], b[2], a[3])
        return m.text(), "groups %d and %d both named %s" % (a[2], b[2], a[3])
    if kind == "view_missing_node":
        if m.view is None:
            return None
        count_line, first, count = m.view
        drop = first + rng.randrange(count)
        m.lines[count_line] = str(count - 1)
        del m.lines[drop]
        return m.text(), "start view without one node"
    raise ValueError(kind)
