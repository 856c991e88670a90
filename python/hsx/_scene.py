"""Scenes in Python: built from halfspace objects, or read from a dict, a JSON string or a file.

Numbers are exact. Accepted: ``int``, ``fractions.Fraction`` (any ``numbers.Rational``), ``decimal.Decimal`` (its
exact decimal value) and exact strings (``"7/3"``, ``"0.1"``, ``"1e-3"``: hsx-scene/1's spellings, read by the
C++ reader). A Python ``float`` is refused with a ``TypeError`` unless ``exact_from_float=True`` is passed, in
which case the float's exact binary value is used: ``0.1`` becomes 3602879701896397/36028797018963968, the double
nearest 1/10, not 1/10 itself (``Fraction(0.1)``).

A Scene holds its hsx-scene/1 document (numbers as JSON integers or exact strings); the C++ reader validates it
when it is arranged (``hsx.arrange``), with the CLI's messages ("halfspaces[2].radius: ...").
"""
from __future__ import annotations

import decimal
import json
import numbers
import os
from fractions import Fraction
from typing import Any, Iterable, List, Optional, Sequence

__all__ = ["exact", "HalfPlane", "Disk", "Polygon", "Sample", "Scene"]


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


def _point(p: Any, where: str, exact_from_float: bool) -> list:
    if isinstance(p, (str, bytes)) or not isinstance(p, Iterable):
        raise TypeError(f"{where}: a point is a pair of numbers, got {type(p).__name__}")
    coords = list(p)
    if len(coords) != 2:
        raise TypeError(f"{where}: a 2D point has 2 coordinates, got {len(coords)}")
    return [exact(x, f"{where}[{k}]", exact_from_float) for k, x in enumerate(coords)]


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


class Sample:
    """A sample on the boundary of halfspace ``on`` (a name or a halfspace object with a name): exactly ``at`` a
    boundary point, or ``near`` a point (snapped exactly to the nearest boundary point)."""

    def __init__(self, on, at=None, near=None, *, exact_from_float: bool = False):
        if (at is None) == (near is None):
            raise TypeError("Sample: give exactly one of at= and near=")
        self.on = on
        self.key = "at" if at is not None else "near"
        self.point = _point(at if at is not None else near, self.key, exact_from_float)

    def to_dict(self) -> dict:
        name = self.on.name if isinstance(self.on, _Halfspace) else self.on
        if not isinstance(name, str):
            raise TypeError("Sample.on: a halfspace name (a halfspace object must have a name)")
        return {"on": name, self.key: self.point}

    def __repr__(self):
        return f"hsx.Sample({self.to_dict()!r})"


class Scene:
    """A 2D scene (hsx-scene/1). Build it from halfspaces and samples, or with from_dict / from_json / from_file.

    ``halfspaces``: HalfPlane, Disk, Polygon objects (unnamed ones are called H0, H1, ... by position);
    ``samples``: Sample objects; ``domain``: ((xmin, ymin), (xmax, ymax)) or None (then hsx chooses one).
    """

    def __init__(self, halfspaces: Sequence[_Halfspace] = (), samples: Sequence[Sample] = (), domain=None,
                 description: Optional[str] = None, *, exact_from_float: bool = False):
        self._doc: dict = {"format": "hsx-scene/1", "dimension": 2}
        if description is not None:
            self._doc["description"] = description
        if domain is not None:
            lo, hi = domain
            self._doc["domain"] = {"min": _point(lo, "domain.min", exact_from_float),
                                   "max": _point(hi, "domain.max", exact_from_float)}
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
        if not isinstance(halfspace, _Halfspace):
            raise TypeError("Scene.add: a HalfPlane, Disk or Polygon")
        entry = halfspace.to_dict(f"H{len(self._doc['halfspaces'])}")
        self._doc["halfspaces"].append(entry)
        return entry["name"]

    def add_sample(self, sample: Sample) -> None:
        if not isinstance(sample, Sample):
            raise TypeError("Scene.add_sample: a Sample")
        self._doc["samples"].append(sample.to_dict())

    def sample(self, on, at=None, near=None, *, exact_from_float: bool = False) -> None:
        """Adds Sample(on, at=..., near=...)."""
        self.add_sample(Sample(on, at=at, near=near, exact_from_float=exact_from_float))

    # -- reading --
    @classmethod
    def from_dict(cls, document: dict, *, exact_from_float: bool = False) -> "Scene":
        """A scene from an hsx-scene/1 document as a dict (numbers made exact; fields checked when arranged)."""
        if not isinstance(document, dict):
            raise TypeError("Scene.from_dict: a dict")
        scene = cls.__new__(cls)
        scene._doc = _normalise(document, "", exact_from_float)
        scene.source = "<dict>"
        return scene

    @classmethod
    def from_json(cls, text: str, source: str = "<json>") -> "Scene":
        """A scene from JSON text; its numbers are read exactly by hsx (0.1 is 1/10), never as floats."""
        scene = cls.__new__(cls)
        scene._doc = None
        scene._text = text
        scene.source = source
        return scene

    @classmethod
    def from_file(cls, path) -> "Scene":
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
        if self._doc is None:
            return f"<hsx.Scene from {self.source}>"
        return (f"<hsx.Scene: {len(self._doc.get('halfspaces', []))} halfspaces, "
                f"{len(self._doc.get('samples', []))} samples>")
