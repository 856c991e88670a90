"""Scenes in Python: built from halfspace objects, or read from a dict, a JSON string or a file.

Numbers are exact. Accepted: ``int``, ``fractions.Fraction`` (any ``numbers.Rational``), ``decimal.Decimal`` (its
exact decimal value) and exact strings (``"7/3"``, ``"0.1"``, ``"1e-3"``: hsx-scene/1's spellings, read by the
C++ reader). A Python ``float`` is refused with a ``TypeError`` unless ``exact_from_float=True`` is passed, in
which case the float's exact binary value is used: ``0.1`` becomes 3602879701896397/36028797018963968, the double
nearest 1/10, not 1/10 itself (``Fraction(0.1)``).

A Scene (2D: HalfPlane, Disk, Polygon) or Scene3 (3D: Plane, Box, Sphere, Cylinder, Cone, Torus, Mesh) holds its
hsx-scene/1 document (numbers as JSON integers or exact strings); the C++ reader validates it when it is arranged
(``hsx.arrange``), with the CLI's messages ("halfspaces[2].radius: ...").
"""
from __future__ import annotations

import decimal
import json
import numbers
import os
from fractions import Fraction
from typing import Any, Iterable, List, Optional, Sequence

__all__ = ["exact", "HalfPlane", "Disk", "Polygon", "Plane", "Box", "Sphere", "Cylinder", "Cone", "Torus", "Mesh",
           "Sample", "Scene", "Scene3"]


def exact(value: Any, where: str = "value", exact_from_float: bool = False):
    """``value`` as an exact hsx-scene/1 number: an int, or a string ("7/3", "0.1").

    ``where`` names the field in error messages. A float is refused (TypeError) unless ``exact_from_float``, then it
    is its exact binary value.
    """
    if isinstance(value, bool):
        raise TypeError(f"{where}: a bool is not a number")
    if isinstance(value, numbers.Integral):
        return int(value)
    if isinstance(value, numbers.Rational):
        q = Fraction(value.numerator, value.denominator)
        return int(q) if q.denominator == 1 else f"{q.numerator}/{q.denominator}"
    if isinstance(value, decimal.Decimal):
        if not value.is_finite():
            raise TypeError(f"{where}: {value!r} is not a finite number")
        q = Fraction(value)
        return int(q) if q.denominator == 1 else f"{q.numerator}/{q.denominator}"
    if isinstance(value, str):
        return value
    if isinstance(value, numbers.Real):  # float, numpy floating
        if not exact_from_float:
            raise TypeError(
                f"{where}: {value!r} is a float, which is not exact (0.1 is not 1/10): pass an int, a "
                f"fractions.Fraction or a string such as \"{value!r}\", or exact_from_float=True to use the float's "
                f"exact binary value")
        f = float(value)
        if f != f or f in (float("inf"), float("-inf")):
            raise TypeError(f"{where}: {value!r} is not a finite number")
        q = Fraction(f)
        return int(q) if q.denominator == 1 else f"{q.numerator}/{q.denominator}"
    raise TypeError(f"{where}: expected an int, a fractions.Fraction or an exact string, got {type(value).__name__}")


def _point(p: Any, where: str, exact_from_float: bool, dimensions=(2,)) -> list:
    """``p`` as a list of exact numbers; its length must be one of ``dimensions``."""
    if isinstance(p, (str, bytes)) or not isinstance(p, Iterable):
        raise TypeError(f"{where}: a point is a {'pair' if dimensions == (2,) else 'tuple'} of numbers, "
                        f"got {type(p).__name__}")
    coords = list(p)
    if len(coords) not in dimensions:
        if len(dimensions) == 1:
            raise TypeError(f"{where}: a {dimensions[0]}D point has {dimensions[0]} coordinates, got {len(coords)}")
        raise TypeError(f"{where}: a point has 2 (2D) or 3 (3D) coordinates, got {len(coords)}")
    return [exact(x, f"{where}[{k}]", exact_from_float) for k, x in enumerate(coords)]


def _point3(p: Any, where: str, exact_from_float: bool) -> list:
    return _point(p, where, exact_from_float, (3,))


def _normalise(value: Any, where: str, exact_from_float: bool) -> Any:
    """A JSON-like tree with every number made exact (dicts, lists and tuples walked; strings, bools, None kept)."""
    if isinstance(value, dict):
        out = {}
        for k, v in value.items():
            if not isinstance(k, str):
                raise TypeError(f"{where}: keys must be strings, got {k!r}")
            out[k] = _normalise(v, f"{where}.{k}" if where else k, exact_from_float)
        return out
    if isinstance(value, (list, tuple)):
        return [_normalise(v, f"{where}[{k}]", exact_from_float) for k, v in enumerate(value)]
    if value is None or isinstance(value, (str, bool)):
        return value
    return exact(value, where or "value", exact_from_float)


class _Halfspace:
    kind = ""
    dimension = 2

    def __init__(self, name: Optional[str], complement: bool):
        self.name = name
        self.complement = bool(complement)
        self._fields: dict = {}

    def to_dict(self, name: Optional[str] = None) -> dict:
        """This halfspace as an hsx-scene/1 entry (``name`` when it has none)."""
        d = {"name": self.name if self.name is not None else name, "kind": self.kind}
        d.update(self._fields)
        if self.complement:
            d["complement"] = True
        return d

    def __invert__(self):
        """The complement (a new object with the same name)."""
        other = type(self).__new__(type(self))
        other.__dict__.update(self.__dict__)
        other.complement = not self.complement
        return other

    def __repr__(self):
        return f"hsx.{type(self).__name__}({self.to_dict(self.name)!r})"


class HalfPlane(_Halfspace):
    """{ x : normal . x <= offset } (``normal`` outward, non-zero, need not be unit)."""
    kind = "halfplane"

    def __init__(self, normal, offset, name: Optional[str] = None, complement: bool = False, *,
                 exact_from_float: bool = False):
        super().__init__(name, complement)
        self._fields = {"normal": _point(normal, "normal", exact_from_float),
                        "offset": exact(offset, "offset", exact_from_float)}


class Disk(_Halfspace):
    """The closed disk { x : |x - center| <= radius }, radius > 0."""
    kind = "disk"

    def __init__(self, center, radius, name: Optional[str] = None, complement: bool = False, *,
                 exact_from_float: bool = False):
        super().__init__(name, complement)
        self._fields = {"center": _point(center, "center", exact_from_float),
                        "radius": exact(radius, "radius", exact_from_float)}


class Polygon(_Halfspace):
    """The closed region bounded by a simple polygon (either vertex order, at least 3 vertices)."""
    kind = "polygon"

    def __init__(self, vertices, name: Optional[str] = None, complement: bool = False, *,
                 exact_from_float: bool = False):
        super().__init__(name, complement)
        self._fields = {"vertices": [_point(v, f"vertices[{k}]", exact_from_float) for k, v in enumerate(vertices)]}


def _segments(value: Any, where: str) -> int:
    if isinstance(value, bool) or not isinstance(value, numbers.Integral):
        raise TypeError(f"{where}: a number of segments is an int, got {type(value).__name__}")
    return int(value)


def _tessellation(segments, edge_length, exact_from_float: bool, minor_segments=None) -> Optional[dict]:
    """hsx-scene/1's "tessellation" from the builders' keywords (None: none given, hsx's default 32 segments). The
    reader checks the combination (one of segments and edge_length; minor_segments with segments, tori only)."""
    t = {}
    if segments is not None:
        t["segments"] = _segments(segments, "tessellation.segments")
    if minor_segments is not None:
        t["minor_segments"] = _segments(minor_segments, "tessellation.minor_segments")
    if edge_length is not None:
        t["edge_length"] = exact(edge_length, "tessellation.edge_length", exact_from_float)
    return t or None


class _Halfspace3(_Halfspace):
    dimension = 3

    def _set(self, fields: dict, tessellation: Optional[dict] = None) -> None:
        self._fields = fields
        if tessellation is not None:
            self._fields["tessellation"] = tessellation


class Plane(_Halfspace3):
    """{ x : normal . x <= offset } in 3D (``normal`` outward, non-zero, need not be unit); clipped to the domain."""
    kind = "plane"

    def __init__(self, normal, offset, name: Optional[str] = None, complement: bool = False, *,
                 exact_from_float: bool = False):
        super().__init__(name, complement)
        self._set({"normal": _point3(normal, "normal", exact_from_float),
                   "offset": exact(offset, "offset", exact_from_float)})


class Box(_Halfspace3):
    """The closed axis-aligned box between opposite corners ``min_corner`` < ``max_corner`` (every coordinate);
    hsx-scene/1's "min" and "max"."""
    kind = "box"

    def __init__(self, min_corner, max_corner, name: Optional[str] = None, complement: bool = False, *,
                 exact_from_float: bool = False):
        super().__init__(name, complement)
        self._set({"min": _point3(min_corner, "min", exact_from_float),
                   "max": _point3(max_corner, "max", exact_from_float)})


class Sphere(_Halfspace3):
    """The ball |x - center| <= radius (radius > 0), tessellated: ``segments`` per full turn of every circle, or
    circles cut into chords of about ``edge_length`` (give at most one; neither: 32 segments). hsx arranges the
    tessellation (docs/scene-format.md says exactly which triangles), never the curved surface."""
    kind = "sphere"

    def __init__(self, center, radius, name: Optional[str] = None, complement: bool = False, *,
                 segments: Optional[int] = None, edge_length=None, exact_from_float: bool = False):
        super().__init__(name, complement)
        self._set({"center": _point3(center, "center", exact_from_float),
                   "radius": exact(radius, "radius", exact_from_float)},
                  _tessellation(segments, edge_length, exact_from_float))


class Cylinder(_Halfspace3):
    """The capped cylinder of ``radius`` about the axis from ``axis_point1`` to ``axis_point2`` (distinct); with
    ``infinite=True`` unbounded along the axis and clipped by the domain box (the scene then needs a domain).
    ``segments`` / ``edge_length`` as for Sphere."""
    kind = "cylinder"

    def __init__(self, axis_point1, axis_point2, radius, name: Optional[str] = None, complement: bool = False, *,
                 infinite: bool = False, segments: Optional[int] = None, edge_length=None,
                 exact_from_float: bool = False):
        super().__init__(name, complement)
        fields = {"axis_point1": _point3(axis_point1, "axis_point1", exact_from_float),
                  "axis_point2": _point3(axis_point2, "axis_point2", exact_from_float),
                  "radius": exact(radius, "radius", exact_from_float)}
        if not isinstance(infinite, bool):
            raise TypeError(f"infinite: a bool, got {type(infinite).__name__}")
        if infinite:
            fields["infinite"] = True
        self._set(fields, _tessellation(segments, edge_length, exact_from_float))


class Cone(_Halfspace3):
    """The solid cone from ``apex`` to its flat base disk of ``radius`` about ``base_center`` (distinct from the
    apex). ``segments`` / ``edge_length`` as for Sphere."""
    kind = "cone"

    def __init__(self, apex, base_center, radius, name: Optional[str] = None, complement: bool = False, *,
                 segments: Optional[int] = None, edge_length=None, exact_from_float: bool = False):
        super().__init__(name, complement)
        self._set({"apex": _point3(apex, "apex", exact_from_float),
                   "base_center": _point3(base_center, "base_center", exact_from_float),
                   "radius": exact(radius, "radius", exact_from_float)},
                  _tessellation(segments, edge_length, exact_from_float))


class Torus(_Halfspace3):
    """The solid ring torus about ``center`` with ``axis`` (non-zero direction), 0 < ``minor_radius`` <
    ``major_radius``. ``segments`` per turn about the axis, ``minor_segments`` around the tube (default:
    ``segments``), or ``edge_length`` instead of both."""
    kind = "torus"

    def __init__(self, center, axis, major_radius, minor_radius, name: Optional[str] = None,
                 complement: bool = False, *, segments: Optional[int] = None, minor_segments: Optional[int] = None,
                 edge_length=None, exact_from_float: bool = False):
        super().__init__(name, complement)
        self._set({"center": _point3(center, "center", exact_from_float),
                   "axis": _point3(axis, "axis", exact_from_float),
                   "major_radius": exact(major_radius, "major_radius", exact_from_float),
                   "minor_radius": exact(minor_radius, "minor_radius", exact_from_float)},
                  _tessellation(segments, edge_length, exact_from_float, minor_segments))


class Mesh(_Halfspace3):
    """The solid bounded by a closed triangle mesh file (.obj, .off or .ply; exact rational or decimal
    coordinates). ``file`` is kept as given: hsx resolves a relative path against the directory of the scene's file
    (Scene.from_file), and for a scene built in Python against the current directory; give an absolute path to be
    independent of it."""
    kind = "mesh"

    def __init__(self, file, name: Optional[str] = None, complement: bool = False):
        super().__init__(name, complement)
        if not isinstance(file, (str, os.PathLike)):
            raise TypeError(f"file: a path, got {type(file).__name__}")
        self._set({"file": os.fspath(file)})


class Sample:
    """A sample on the boundary of halfspace ``on`` (a name or a halfspace object with a name): exactly ``at`` a
    boundary point, or ``near`` a point (snapped exactly to the nearest boundary point; 3D: of the tessellated
    surface). Points have 2 coordinates in a Scene, 3 in a Scene3."""

    def __init__(self, on, at=None, near=None, *, exact_from_float: bool = False):
        if (at is None) == (near is None):
            raise TypeError("Sample: give exactly one of at= and near=")
        self.on = on
        self.key = "at" if at is not None else "near"
        self.point = _point(at if at is not None else near, self.key, exact_from_float, (2, 3))

    @property
    def dimension(self) -> int:
        return len(self.point)

    def to_dict(self) -> dict:
        name = self.on.name if isinstance(self.on, _Halfspace) else self.on
        if not isinstance(name, str):
            raise TypeError("Sample.on: a halfspace name (a halfspace object must have a name)")
        return {"on": name, self.key: self.point}

    def __repr__(self):
        return f"hsx.Sample({self.to_dict()!r})"


def _dimension_of(document) -> Optional[int]:
    """A document's dimension: its "dimension" field, 3 for a BSH authors' config.json (an "input" and no
    "format", io/bsh_config.hpp), None when it has neither (hsx reports what is wrong when it is arranged)."""
    if not isinstance(document, dict):
        return None
    if "format" not in document and "input" in document:
        return 3
    d = document.get("dimension")
    return d if isinstance(d, int) and not isinstance(d, bool) else None


class Scene:
    """A 2D scene (hsx-scene/1); Scene3 is the 3D one. Build it from halfspaces and samples, or with from_dict /
    from_json / from_file (on Scene, these give a Scene3 for a document of dimension 3).

    ``halfspaces``: HalfPlane, Disk, Polygon objects (unnamed ones are called H0, H1, ... by position);
    ``samples``: Sample objects; ``domain``: ((xmin, ymin), (xmax, ymax)) or None (then hsx chooses one);
    ``description``: the document's description.
    """
    dimension = 2
    _kinds = "a HalfPlane, Disk or Polygon"

    def __init__(self, halfspaces: Sequence[_Halfspace] = (), samples: Sequence[Sample] = (), domain=None,
                 description: Optional[str] = None, *, exact_from_float: bool = False):
        self._doc: dict = {"format": "hsx-scene/1", "dimension": self.dimension}
        if description is not None:
            self._doc["description"] = description
        if domain is not None:
            lo, hi = domain
            dims = (self.dimension,)
            self._doc["domain"] = {"min": _point(lo, "domain.min", exact_from_float, dims),
                                   "max": _point(hi, "domain.max", exact_from_float, dims)}
        self._doc["halfspaces"] = []
        self._doc["samples"] = []
        for h in halfspaces:
            self.add(h)
        for s in samples:
            self.add_sample(s)
        self.source = "<scene>"

    # -- building --
    def add(self, halfspace: _Halfspace) -> str:
        """Adds a halfspace; returns its name."""
        if not isinstance(halfspace, _Halfspace) or halfspace.dimension != self.dimension:
            got = (f"a {halfspace.dimension}D {type(halfspace).__name__}" if isinstance(halfspace, _Halfspace)
                   else type(halfspace).__name__)
            raise TypeError(f"{type(self).__name__}.add: {self._kinds}, got {got}")
        entry = halfspace.to_dict(f"H{len(self._doc['halfspaces'])}")
        self._doc["halfspaces"].append(entry)
        return entry["name"]

    def add_sample(self, sample: Sample) -> None:
        if not isinstance(sample, Sample):
            raise TypeError(f"{type(self).__name__}.add_sample: a Sample")
        if sample.dimension != self.dimension:
            raise TypeError(f"{type(self).__name__}.add_sample: the sample's point has {sample.dimension} "
                            f"coordinates; a {self.dimension}D scene needs {self.dimension}")
        self._doc["samples"].append(sample.to_dict())

    def sample(self, on, at=None, near=None, *, exact_from_float: bool = False) -> None:
        """Adds Sample(on, at=..., near=...)."""
        self.add_sample(Sample(on, at=at, near=near, exact_from_float=exact_from_float))

    # -- reading --
    @classmethod
    def _class_for(cls, dimension: Optional[int]):
        """The class a document of ``dimension`` gets: Scene dispatches (3 -> Scene3); Scene3 refuses 2D."""
        if cls is Scene:
            return Scene3 if dimension == 3 else Scene
        if dimension is not None and dimension != cls.dimension:
            from ._hsx import InputError
            raise InputError(f"dimension: expected {cls.dimension}, got {dimension} (use hsx.Scene)")
        return cls

    @classmethod
    def from_dict(cls, document: dict, *, exact_from_float: bool = False) -> "Scene":
        """A scene from an hsx-scene/1 document as a dict (numbers made exact; fields checked when arranged)."""
        if not isinstance(document, dict):
            raise TypeError(f"{cls.__name__}.from_dict: a dict")
        target = cls._class_for(_dimension_of(document))
        scene = target.__new__(target)
        scene._doc = _normalise(document, "", exact_from_float)
        scene.source = "<dict>"
        return scene

    @classmethod
    def from_json(cls, text: str, source: str = "<json>") -> "Scene":
        """A scene from JSON text; its numbers are read exactly by hsx (0.1 is 1/10), never as floats. ``source``
        names it in messages; a mesh file is found relative to its directory."""
        try:  # only to see the dimension: the text itself is what hsx reads
            dimension = _dimension_of(json.loads(text, parse_float=str))
        except ValueError:
            dimension = None  # not JSON: hsx reports it when the scene is arranged
        target = cls._class_for(dimension)
        scene = target.__new__(target)
        scene._doc = None
        scene._text = text
        scene.source = source
        return scene

    @classmethod
    def from_file(cls, path) -> "Scene":
        """A scene from a file (read as from_json; relative mesh paths are the file's directory's)."""
        with open(os.fspath(path), encoding="utf-8") as f:
            return cls.from_json(f.read(), source=os.fspath(path))

    # -- writing --
    def to_json(self) -> str:
        """The hsx-scene/1 JSON text (exact: numbers are JSON integers or strings)."""
        if self._doc is None:
            return self._text
        return json.dumps(self._doc, indent=2) + "\n"

    def to_dict(self) -> dict:
        """The document as a dict whose numbers are ints or exact strings. For a scene read from JSON text, its
        decimals come back as exact strings (via hsx's exact reader)."""
        if self._doc is None:
            from . import arrange  # the reader keeps decimals exact; the arranged scene's writer gives strings
            return json.loads(arrange(self).scene_json())
        return json.loads(json.dumps(self._doc))

    @property
    def halfspace_names(self) -> List[str]:
        return [h.get("name") for h in self.to_dict().get("halfspaces", [])]

    def _repr_svg_(self):
        from . import arrange
        try:
            return arrange(self)._repr_svg_()
        except Exception:  # a scene that does not arrange has no picture
            return None

    def __repr__(self):
        name = type(self).__name__
        if self._doc is None:
            return f"<hsx.{name} from {self.source}>"
        return (f"<hsx.{name}: {len(self._doc.get('halfspaces', []))} halfspaces, "
                f"{len(self._doc.get('samples', []))} samples>")


class Scene3(Scene):
    """A 3D scene (hsx-scene/1, dimension 3), built like Scene: ``halfspaces``: Plane, Box, Sphere, Cylinder,
    Cone, Torus, Mesh objects; ``samples``: Sample objects with 3 coordinates; ``domain``: ((xmin, ymin, zmin),
    (xmax, ymax, zmax)) or None (hsx chooses one; an infinite cylinder needs one). hsx.arrange, extract, check and
    grade take it as they take a Scene."""
    dimension = 3
    _kinds = "a Plane, Box, Sphere, Cylinder, Cone, Torus or Mesh"
