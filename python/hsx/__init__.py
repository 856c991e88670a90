"""hsx from Python: exact arrangements of halfspaces, the BSH shape, CSG and proposition checks.

    import hsx
    from fractions import Fraction as F
    scene = hsx.Scene([hsx.Disk((0, 0), 2, "A"), hsx.HalfPlane((0, 1), F(3, 2), "C")])
    scene.sample("A", at=(-2, 0))
    cx = hsx.arrange(scene)                        # hsx.Complex: cells, patches, junctions, samples
    r = hsx.extract(cx, method="exact")            # hsx.Result: labelling (numpy bool), energy, ties, stats
    r.energy.measure.exact                         # '2/3*pi + ...', exact; float(r.energy.measure) for plotting

    scene3 = hsx.Scene3([hsx.Sphere((0, 0, 0), 2, "S", segments=16), hsx.Box((0, 0, 0), (3, 3, 3), "B")])
    r3 = hsx.extract(scene3, method="graphcut")    # 3D: r3.volume exact, r3.boundary_mesh() numpy arrays

Every function takes a scene as an hsx.Scene, a dict, JSON text (a string starting with "{") or a file path, or
an hsx.Complex already arranged. Bad input raises hsx.InputError (a ValueError) with the hsx program's message;
a Python float where an exact number is expected raises TypeError unless exact_from_float=True (hsx/_scene.py).
Long computations release the GIL and stop on Ctrl-C (KeyboardInterrupt) or through an hsx.CancelToken.
See docs/python.md.
"""
from __future__ import annotations

import json
import os
from typing import Any, Callable, Iterator, Optional

from . import _hsx
from ._hsx import (CancelToken, Cell, CheckResult, Complex, Conversion, CsgTree, Describability, Energy, Grade,
                   InputError, Junction, Measure, NhTree, Order, Patch, Result, SampleSite, Samples, Ties, Undecided,
                   compare)
from ._campaign import Campaign, CampaignRecord, campaign, campaign_checks
from ._scene import (Box, Cone, Cylinder, Disk, HalfPlane, Mesh, Plane, Polygon, Sample, Scene, Scene3, Sphere, Torus,
                     exact)

__all__ = ["CancelToken", "Cell", "CheckResult", "Complex", "Conversion", "CsgTree", "Describability", "Energy",
           "Grade", "InputError", "Junction", "Measure", "NhTree", "Order", "Patch", "Result", "SampleSite", "Samples",
           "Ties", "Undecided", "compare", "Disk", "HalfPlane", "Polygon", "Plane", "Box", "Sphere", "Cylinder", "Cone",
           "Torus", "Mesh", "Sample", "Scene", "Scene3", "exact", "arrange",
           "load", "extract", "grade", "check", "solid", "describe", "csg", "samples", "convert", "nhtree",
           "random_scene", "random_scenes", "METHODS", "DEGENERACIES", "Campaign", "CampaignRecord", "campaign",
           "campaign_checks", "export_graphcut"]

METHODS = ("graphcut", "beam", "best-first", "brute-force", "exact")
DEGENERACIES = _hsx.DEGENERACIES
_MAX_CELLS = 250000
_MAX_SIDE_TABLE = 1 << 27


def _measure_sympy(self: Measure):
    """The measure as a sympy expression (exact), when it has a closed form; needs sympy."""
    try:
        import sympy
    except ImportError as e:
        raise ImportError("Measure.sympy() needs sympy (Debian: python3-sympy)") from e
    text = self.exact
    if text is None:
        raise ValueError("this measure has no closed form (an arc angle that is not a multiple of pi/12); use "
                         "interval() or decimal()")
    return sympy.sympify(text, rational=True)


Measure.sympy = _measure_sympy


def _patch_polylines(self: Complex, arc_points: int = 32):
    """Per patch, its pieces as (n, 2) float arrays for plotting (arcs sampled with arc_points points)."""
    from ._draw import patch_polylines
    return patch_polylines(self, arc_points)


def _cell_outlines(self: Complex, arc_points: int = 32):
    """Per cell, its boundary loops (outer boundary, then holes) as closed (n, 2) float arrays for plotting."""
    from ._draw import cell_outlines
    return cell_outlines(self, arc_points)


Complex.patch_polylines = _patch_polylines
Complex.cell_outlines = _cell_outlines


def load(source, *, max_cells: int = _MAX_CELLS, max_side_table: int = _MAX_SIDE_TABLE) -> Complex:
    """A scene (arranged exactly) or an hsx-complex/1 document, from a file path or JSON text; the same as
    arrange()."""
    return arrange(source, max_cells=max_cells, max_side_table=max_side_table)


def arrange(scene, *, max_cells: int = _MAX_CELLS, max_side_table: int = _MAX_SIDE_TABLE,
            exact_from_float: bool = False) -> Complex:
    """The exact arrangement of ``scene`` as an hsx.Complex.

    ``scene``: an hsx.Scene, a dict (hsx-scene/1 or hsx-complex/1; numbers as in hsx.exact), JSON text (a string
    starting with "{"), a file path (str or os.PathLike), or a Complex (returned as is). ``max_cells``,
    ``max_side_table``: the arrangement's size limits (docs/limits.md; 0: no limit), refused beyond them with
    InputError.
    """
    if isinstance(scene, Complex):
        return scene
    if isinstance(scene, Scene):
        return _hsx._load_text(scene.to_json(), scene.source, max_cells, max_side_table)
    if isinstance(scene, dict):
        doc = Scene.from_dict(scene, exact_from_float=exact_from_float)
        return _hsx._load_text(doc.to_json(), "", max_cells, max_side_table)
    if isinstance(scene, str) and scene.lstrip().startswith("{"):
        return _hsx._load_text(scene, "", max_cells, max_side_table)
    if isinstance(scene, (str, os.PathLike)):
        return _hsx._load_file(os.fspath(scene), max_cells, max_side_table)
    raise TypeError("arrange: an hsx.Scene, a dict, JSON text, a file path or an hsx.Complex, got "
                    f"{type(scene).__name__}")


def extract(scene_or_complex, method: str = "beam", *, beam_width: int = 1, max_states: int = 0,
            max_graph_cuts: int = 0, max_nodes: int = 0, time_limit: float = 0,
            max_labellings: int = _hsx.DEFAULT_MAX_LABELLINGS, max_ties: int = 16, enumerate_ties: bool = True,
            precision: int = 2048, record_states: bool = False,
            progress: Optional[Callable[[dict], Any]] = None, cancel: Optional[CancelToken] = None) -> Result:
    """The BSH shape by ``method`` (one of hsx.METHODS; "best_first" is accepted for "best-first").

    Limits as `hsx extract`'s options: ``max_states``, ``max_graph_cuts``, ``max_nodes`` (exact) are
    deterministic; ``time_limit`` (seconds) is not; a limit returns the best sample-connected boundary found so far
    with ``optimal`` False and ``stopped_by`` naming it. ``max_labellings``: brute force refuses more
    (InputError). ``precision``: the bits at which unseparated measures are reported as ties. ``record_states``:
    keep every expanded state (Result.expanded). ``progress``: called about twice a second with a dict
    (states_expanded, queue_size, graph_cuts, best_energy, lower_bound); an exception it raises stops the search
    and propagates. ``cancel``: an hsx.CancelToken; its cancel() stops the search (stopped_by "cancelled").
    Ctrl-C raises KeyboardInterrupt.
    """
    cx = arrange(scene_or_complex)
    return _hsx._extract(cx, method, beam_width, max_states, max_graph_cuts, max_nodes, time_limit, max_labellings,
                         max_ties, enumerate_ties, precision, record_states, progress, cancel)


def grade(scene_or_complex, labelling, *, oracle: str = "best-first", time_limit: float = 0,
          progress: Optional[Callable[[dict], Any]] = None, cancel: Optional[CancelToken] = None) -> Grade:
    """Grades a labelling computed elsewhere exactly (`hsx grade`): validity (Def. 3.1, 3.2), its energy and the
    gap to the optimum computed by ``oracle``.

    ``labelling``: one 0/1 or bool per cell in the complex's cell order (a sequence or numpy array), or a document
    as `hsx grade` reads it (io/labelling.hpp): a dict (the BSH authors' ``{"labels": [...]}`` or an hsx-result/1,
    whose complex_id must match), JSON text (a string starting with "{" or "["), or the path of a file holding
    either or a plain list of 0/1 tokens."""
    cx = arrange(scene_or_complex)
    return _hsx._grade(cx, _labelling(cx, labelling), oracle, time_limit, progress, cancel)


def _labelling(cx: Complex, labelling):
    """grade()'s labelling as per-cell flags (a sequence is passed on as it is)."""
    if isinstance(labelling, dict):
        return _hsx._labelling_text(cx, json.dumps(labelling), "labelling")
    if isinstance(labelling, str) and labelling.lstrip().startswith(("{", "[")):
        return _hsx._labelling_text(cx, labelling, "labelling")
    if isinstance(labelling, (str, os.PathLike)):
        return _hsx._labelling_file(cx, os.fspath(labelling))
    return labelling


def export_graphcut(scene_or_complex, weight_scale: int = _hsx.DEFAULT_GRAPHCUT_WEIGHT_SCALE) -> dict:
    """The complex as the BSH authors' graph-cut input (`hsx arrange --export bsh-graphcut FILE`, io/labelling.hpp):
    num_cells, patches (adj_cell_0 outside, adj_cell_1 inside, weight = round(measure * weight_scale) at least 1,
    implicit_id, num_samples, adj_patches) and hsx's extra fields (format, complex_id, weight_scale, outer_cells,
    per patch measure, measure_exact, support). Their tool's {"labels": [...]} answer goes to grade(). Raises
    InputError when weight_scale < 1 or a weight would exceed 2^53."""
    cx = arrange(scene_or_complex)
    return json.loads(_hsx._export_graphcut(cx, weight_scale))


def check(scene_or_complex, *, max_labellings: int = 200000, time_limit: float = 0, max_states: int = 0,
          max_graph_cuts: int = 0, precision: int = 2048, cancel: Optional[CancelToken] = None) -> list:
    """Every proposition checker (`hsx check`): a list of hsx.CheckResult (name, status, witness). Limits as
    extract's; a check they cut short is 'stopped', one they leave no time for 'skipped'."""
    cx = arrange(scene_or_complex)
    return _hsx._check(cx, max_labellings, time_limit, max_states, max_graph_cuts, precision, cancel)


def solid(scene_or_complex, csg: Optional[str] = None, shape=None, *, mesh=None):
    """A solid of the complex's cells as a numpy bool array, from exactly one of: ``csg``, a CSG expression over
    the halfspace names ("(A | B) & ~C", io/csg_text.hpp), ``shape``: an hsx.Result, an hsx-result/1 document
    (dict, JSON text or file path; its complex_id must match) or a per-cell sequence of bools, and (3D scenes)
    ``mesh``: the path of a closed triangle mesh (.obj, .off, .ply) whose faces lie on the scene's halfspaces, the
    solid being the cells inside it (`--mesh`, docs/csg3.md; a face off the halfspaces raises InputError naming
    it)."""
    cx = arrange(scene_or_complex)
    if (csg is not None) + (shape is not None) + (mesh is not None) != 1:
        raise InputError("give exactly one of csg=, shape= and mesh=")
    if csg is not None:
        return _hsx._solid_from_csg(cx, csg)
    if mesh is not None:
        return _hsx._solid_from_mesh(cx, os.fspath(mesh))
    if isinstance(shape, Result):
        if shape.complex.identity != cx.identity:
            raise InputError("shape: the result was computed from another input (its complex_id differs)")
        return shape.labelling
    if isinstance(shape, dict):
        return _hsx._result_labelling(cx, json.dumps(shape))
    if isinstance(shape, str) and shape.lstrip().startswith("{"):
        return _hsx._result_labelling(cx, shape)
    if isinstance(shape, (str, os.PathLike)):
        with open(os.fspath(shape), encoding="utf-8") as f:
            text = f.read()
        try:
            return _hsx._result_labelling(cx, text)
        except InputError as e:
            raise InputError(f"{os.fspath(shape)}: {e}") from None
    return _hsx._flags(cx, shape)


def describe(scene_or_complex, csg: Optional[str] = None, shape=None, *, mesh=None) -> Describability:
    """Shapiro-Vossler describability of a solid (see solid()) by the halfspaces, with the mixed terms."""
    cx = arrange(scene_or_complex)
    return _hsx._describe(cx, solid(cx, csg=csg, shape=shape, mesh=mesh))


def csg(scene_or_complex, csg: Optional[str] = None, shape=None, *, mesh=None, separators: bool = False,
        max_separators: int = 8) -> CsgTree:
    """Buchele-Crawford's BHC tree of a solid (see solid()), verified on every cell (`hsx csg`); with
    ``separators``, separating half-planes are added first when the solid is not describable."""
    cx = arrange(scene_or_complex)
    return _hsx._csg(cx, solid(cx, csg=csg, shape=shape, mesh=mesh), separators, max_separators)


def samples(scene_or_complex, target=None, csg: Optional[str] = None, *, mesh=None, search: str = "beam",
            beam_width: int = 1, exhaustive_patches: int = 14) -> Samples:
    """GENERATE-SAMPLES (BSH Fig. 12): samples that make extraction give back ``target`` (a solid as in solid()'s
    shape=), the solid of ``csg`` or (3D) the cells inside ``mesh``; with the lower and upper bounds and the
    exhaustive minimum."""
    cx = arrange(scene_or_complex)
    cells = solid(cx, csg=csg, shape=target, mesh=mesh)
    return _hsx._samples(cx, cells, search, beam_width, exhaustive_patches)


def convert(scene_or_complex=None, csg: Optional[str] = None, shape=None, *, mesh=None, csgnet: Optional[str] = None,
            search: str = "beam") -> Conversion:
    """A CSG solid as a BSH scene (`hsx convert`, BSH Section 6): the solid (see solid()) of a 2D or 3D scene, or a
    CSGNet program (``csgnet="c(32,32,16)s(32,40,12)-"``, which defines both). ``search``: "beam" or "best-first",
    for GENERATE-SAMPLES and the round trip. ``Conversion.scene_json()`` is the scene; ``ok`` says it extracts
    back; in 3D, ``inside_cells``, ``cells``, ``patches`` and ``volume`` are those of the oriented scene's complex
    the samples are on (`hsx convert --json`'s)."""
    if csgnet is not None:
        if scene_or_complex is not None or csg is not None or shape is not None or mesh is not None:
            raise InputError("csgnet: give the program alone (it defines the scene and the solid)")
        return _hsx._convert_csgnet(csgnet, search)
    if scene_or_complex is None:
        raise InputError("give a scene with csg=, shape= or mesh=, or csgnet=")
    cx = arrange(scene_or_complex)
    return _hsx._convert(cx, solid(cx, csg=csg, shape=shape, mesh=mesh), search)


def nhtree(scene_or_complex, csg: Optional[str] = None, shape=None, *, nest_holes: bool = False) -> NhTree:
    """NH-Rep's Boolean tree of a 2D solid (see solid()): Algorithm 1 with patch decomposition as the paper reads
    it, the structural checks and the exact evaluation with natural halfspaces (`hsx nhtree SCENE --csg E`).
    ``nest_holes``: intersect holes with their part (an extension). Meshes: use the hsx program."""
    cx = arrange(scene_or_complex)
    return _hsx._nhtree(cx, solid(cx, csg=csg, shape=shape), nest_holes)


def random_scene(seed: int, index: int = 0, **settings) -> Scene:
    """Scene ``index`` of ``seed`` from hsx's random generator (geometry/random_scene.hpp: reproducible on every
    machine). ``settings``: RandomSceneSettings' fields (min_halfspaces, max_halfspaces, halfplanes, disks,
    polygons, complement_percent, denominator, coordinate_bound, max_radius, min_degeneracies, max_degeneracies,
    max_samples, near_percent) and degeneracy_weights (a dict over hsx.DEGENERACIES). The scene's ``degeneracies``
    lists the patterns applied."""
    text, degeneracies = _hsx._random_scene(seed, index, settings)
    scene = Scene.from_json(text, source=f"<random scene {seed}/{index}>")
    scene.degeneracies = list(degeneracies)
    return scene


def random_scenes(seed: int, count: Optional[int] = None, start: int = 0, **settings) -> Iterator[Scene]:
    """random_scene(seed, index) for index = start, start + 1, ... (``count`` of them, or without end)."""
    index = start
    while count is None or index < start + count:
        yield random_scene(seed, index, **settings)
        index += 1
