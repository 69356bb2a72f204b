# adhesiveWallInteraction | SPDX-License-Identifier: GPL-3.0-or-later
"""A case's constant/polyMesh in Python (ASCII, or gzip-compressed ASCII;
a reconstructed mesh; a binary file is refused by name): the patches'
areas, the domain's volume, the cells' volumes and the cells on given
patches.

Each face is split into a fan of triangles from its first point: a face's
area vector is the sum of its triangles', a patch's area the sum of its
faces' triangles' areas; a cell's volume is (1/6) sum a.(b x c) over the
triangles of its faces, oriented out of it (Gauss; exact for the
triangulated faces), and the domain's the same over the boundary.
"""

import gzip
import os
import re

import numpy as np


def _text(path):
    """A mesh file's text (path or path.gz); a binary file is refused."""
    for name, opener in ((path, open), (path + ".gz", gzip.open)):
        if os.path.isfile(name):
            with opener(name, "rt") as handle:
                text = handle.read()
            if re.search(r"\bformat\s+binary\s*;", text):
                raise ValueError(
                    f"{name} is binary: convert it (foamFormatConvert with "
                    f"writeFormat ascii) or give the areas and volume")
            return text
    raise FileNotFoundError(path)


def _after_header(text):
    """The text after the FoamFile header."""
    match = re.search(r"FoamFile\s*\{[^}]*\}", text)
    return text[match.end():] if match else text


def read_points(path):
    body = _after_header(_text(path))
    start = body.index("(")
    numbers = re.findall(r"[-+0-9.eE]+", body[start:body.rindex(")")])
    return np.array([float(x) for x in numbers]).reshape(-1, 3)


def read_faces(path):
    """The faces of a faceList as lists of point labels."""
    body = _after_header(_text(path))
    body = body[body.index("(") + 1:]
    return [[int(x) for x in labels.split()]
            for labels in re.findall(r"\d+\s*\(([\d\s]+)\)", body)]


def read_boundary(path):
    """{patch: (startFace, nFaces)}."""
    body = _after_header(_text(path))
    patches = {}
    for name, entries in re.findall(r"([^\s(){};]+)\s*\{([^}]*)\}", body):
        n = re.search(r"\bnFaces\s+(\d+)\s*;", entries)
        s = re.search(r"\bstartFace\s+(\d+)\s*;", entries)
        if n and s:
            patches[name] = (int(s.group(1)), int(n.group(1)))
    return patches


def areas_and_volume(case="."):
    """The boundary patches' areas [m^2] and the domain's volume [m^3]."""
    points, faces = _points_and_faces(case)
    mesh = _folder(case)
    areas, volume = {}, 0.0
    boundary = read_boundary(os.path.join(mesh, "boundary"))
    for name, (start, n) in boundary.items():
        area = 0.0
        for face in faces[start:start + n]:
            a = points[face[0]]
            for i in range(1, len(face) - 1):
                b, c = points[face[i]], points[face[i + 1]]
                area += 0.5*np.linalg.norm(np.cross(b - a, c - a))
                volume += np.dot(a, np.cross(b, c))/6
        areas[name] = area
    return areas, volume


def _folder(case):
    return os.path.join(case, "constant", "polyMesh")


def _points_and_faces(case):
    mesh = _folder(case)
    return (read_points(os.path.join(mesh, "points")),
            read_faces(os.path.join(mesh, "faces")))


def read_labels(path):
    """A labelList (owner, neighbour)."""
    body = _after_header(_text(path))
    body = body[body.index("(") + 1:body.rindex(")")]
    return [int(x) for x in body.split()]


def cell_volumes(case):
    """The volume of every cell [m^3]."""
    points, faces = _points_and_faces(case)
    owner = read_labels(os.path.join(_folder(case), "owner"))
    neighbour = read_labels(os.path.join(_folder(case), "neighbour"))
    # (the last cells may own no face: count them from the neighbours too)
    volumes = np.zeros(max(owner + neighbour) + 1)
    for i, face in enumerate(faces):
        a = points[face[0]]
        v = sum(np.dot(a, np.cross(points[face[k]], points[face[k + 1]]))
                for k in range(1, len(face) - 1))/6
        volumes[owner[i]] += v
        if i < len(neighbour):
            volumes[neighbour[i]] -= v
    return volumes


def cells_on(case, patches):
    """The cells that have a face on one of the patches named."""
    owner = read_labels(os.path.join(_folder(case), "owner"))
    boundary = read_boundary(os.path.join(_folder(case), "boundary"))
    cells = set()
    for name in patches:
        start, n = boundary[name]
        cells.update(owner[start:start + n])
    return sorted(cells)
