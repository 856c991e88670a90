# Type stubs of the extension module hsx._hsx (python/src). Use the package hsx, which re-exports these.
from fractions import Fraction
from typing import Any, Callable, Dict, Iterator, List, Optional, Sequence, Tuple, Union
import enum

import numpy as np
import numpy.typing as npt

Number = Union[int, Fraction, str]
BoolArray = npt.NDArray[np.bool_]

class InputError(ValueError): ...
class Undecided(ArithmeticError): ...

class Order(enum.Enum):
    Less: int
    Equal: int
    Greater: int
    Tie: int

class Measure:
    def __init__(self, value: Number = 0) -> None: ...
    @staticmethod
    def sqrt(q: Number) -> Measure: ...
    @staticmethod
    def pi(coefficient: Number = 1) -> Measure: ...
    @property
    def exact(self) -> Optional[str]: ...
    def decimal(self, digits: int = 30) -> str: ...
    def decimal_certified(self, digits: int = 30) -> bool: ...
    def __float__(self) -> float: ...
    def interval(self, bits: int = 128) -> Tuple[Fraction, Fraction]: ...
    def float_interval(self, bits: int = 128) -> Tuple[float, float]: ...
    def sign(self, max_bits: int = 2048) -> Optional[int]: ...
    def compare(self, other: Union[Measure, Number], max_bits: int = 2048) -> Order: ...
    @property
    def rational(self) -> Optional[Fraction]: ...
    @property
    def pi_coefficient(self) -> Fraction: ...
    def is_zero(self) -> bool: ...
    def is_algebraic(self) -> bool: ...
    def sympy(self) -> Any: ...
    def __neg__(self) -> Measure: ...
    def __add__(self, other: Union[Measure, int, Fraction]) -> Measure: ...
    def __radd__(self, other: Union[Measure, int, Fraction]) -> Measure: ...
    def __sub__(self, other: Union[Measure, int, Fraction]) -> Measure: ...
    def __rsub__(self, other: Union[Measure, int, Fraction]) -> Measure: ...
    def __mul__(self, factor: Union[int, Fraction]) -> Measure: ...
    def __rmul__(self, factor: Union[int, Fraction]) -> Measure: ...
    def __lt__(self, other: Union[Measure, int, Fraction]) -> bool: ...
    def __le__(self, other: Union[Measure, int, Fraction]) -> bool: ...
    def __gt__(self, other: Union[Measure, int, Fraction]) -> bool: ...
    def __ge__(self, other: Union[Measure, int, Fraction]) -> bool: ...

def compare(a: Measure, b: Measure, max_bits: int = 2048) -> Order: ...

class CancelToken:
    def __init__(self) -> None: ...
    def cancel(self) -> None: ...
    @property
    def cancelled(self) -> bool: ...

class Cell:
    index: int
    outer: bool
    witness: Tuple[Fraction, ...]
    sides: Dict[str, bool]
    inside: List[str]
    measure: Measure

class Patch:
    index: int
    halfspace: str
    halfspace_index: int
    inside_cell: int
    outside_cell: int
    cells: Tuple[int, int]
    samples: List[int]
    measure: Measure
    support: int
    junctions: List[int]

class Junction:
    index: int
    patches: List[int]

class SampleSite:
    index: int
    halfspace: str
    patch: int

class Complex:
    dimension: int
    halfspaces: List[str]
    cells: List[Cell]
    patches: List[Patch]
    junctions: List[Junction]
    samples: List[SampleSite]
    supports: List[List[int]]
    outer_cell_count: int
    identity: str
    has_scene: bool
    source: str
    def cell_patches(self) -> List[List[int]]: ...
    def patch_neighbours(self) -> List[List[int]]: ...
    def measure_of(self, patches: Sequence[int]) -> Measure: ...
    def validate(self) -> List[str]: ...
    def scene_json(self) -> Optional[str]: ...
    def to_json(self) -> str: ...
    def svg(self, labels: bool = False, width: int = 800, title: str = "",
            fill: Optional[Union[Sequence[bool], BoolArray]] = None, highlight: Optional[Sequence[int]] = None,
            highlight_legend: str = "highlighted patches",
            views: Optional[Sequence[Union[str, Tuple[str, Sequence[Number], Sequence[Number]]]]] = None
            ) -> Optional[str]: ...
    def _repr_svg_(self) -> Optional[str]: ...
    def surface_mesh(self, exact: bool = False) -> Tuple[Union[npt.NDArray[np.float64], List[Tuple[str, str, str]]],
                                                         npt.NDArray[np.int64], npt.NDArray[np.int64],
                                                         npt.NDArray[np.int64]]: ...
    def patch_polylines(self, arc_points: int = 32) -> List[List[npt.NDArray[np.float64]]]: ...
    def cell_outlines(self, arc_points: int = 32) -> List[List[npt.NDArray[np.float64]]]: ...

class Energy:
    missing_samples: int
    measure: Measure
    def compare(self, other: Energy, max_bits: int = 2048) -> Order: ...
    def __iter__(self) -> Iterator[Any]: ...

class Ties:
    count: int
    checked: bool
    certified: bool
    capped: bool
    stopped_by: str

class Result:
    complex: Complex
    method: str
    optimal: bool
    labelling: BoolArray
    inside_cells: List[int]
    energy: Energy
    area: Measure
    volume: Measure
    sample_connected: bool
    boundary_patches: List[int]
    def boundary_mesh(self, exact: bool = False) -> Tuple[Union[npt.NDArray[np.float64], List[Tuple[str, str, str]]],
                                                          npt.NDArray[np.int64], npt.NDArray[np.int64],
                                                          npt.NDArray[np.int64]]: ...
    removed_patches: List[int]
    steps: List[List[int]]
    ties: Ties
    tied: List[BoolArray]
    stopped_by: str
    optimality_note: str
    expanded: List[BoolArray]
    stats: Dict[str, Any]
    def to_json(self, include_seconds: bool = False) -> str: ...
    def svg(self, show_removed: bool = False, labels: bool = False, width: int = 800, title: str = "",
            views: Optional[Sequence[Union[str, Tuple[str, Sequence[Number], Sequence[Number]]]]] = None
            ) -> Optional[str]: ...
    def _repr_svg_(self) -> Optional[str]: ...

class Grade:
    orientation_preserving: bool
    orientation_problem: str
    sample_connected: bool
    islands: List[Dict[str, Any]]
    energy: Energy
    optimum: Result
    versus_optimum: Order
    missing_samples_gap: int
    measure_gap: Measure
    optimal: bool

class CheckResult:
    name: str
    status: str
    witness: str

class Describability:
    describable: bool
    terms: int
    mixed: List[Dict[str, Any]]
    def svg(self, labels: bool = False) -> Optional[str]: ...
    def _repr_svg_(self) -> Optional[str]: ...
    def __bool__(self) -> bool: ...

class CsgTree:
    describable: bool
    verified: bool
    text: Optional[str]
    stats: Dict[str, int]
    mixed: List[Dict[str, Any]]
    separated_scene_json: Optional[str]
    def __bool__(self) -> bool: ...

class Samples:
    sample_patches: List[int]
    count: int
    lower_bound: int
    upper_bound: int
    rounds: int
    reproduced: bool
    fallbacks: int
    used_sufficient_set: bool
    failure: str
    minimum: Optional[int]
    def scene_json(self, description: str = ...) -> Optional[str]: ...

class Conversion:
    ok: bool
    dimension: int
    round_trip: bool
    failure: str
    flipped: List[str]
    samples: int
    sample_patches: List[int]
    lower_bound: int
    upper_bound: int
    rounds: int
    cells: Optional[int]
    patches: Optional[int]
    inside_cells: Optional[List[int]]
    volume: Optional[Measure]
    def scene_json(self) -> str: ...
    def __bool__(self) -> bool: ...

class NhTree:
    tree: str
    tree_ids: str
    conf: str
    leaf_names: List[str]
    decompositions: int
    structure_violations: List[str]
    verdict: str
    correct: bool
    describable: bool
    evaluation_violations: List[str]
    missed: List[Tuple[Fraction, ...]]
    added: List[Tuple[Fraction, ...]]
    def to_json(self) -> str: ...
    def svg(self) -> str: ...
    def _repr_svg_(self) -> str: ...

DEGENERACIES: Tuple[str, ...]
DEFAULT_MAX_LABELLINGS: int
DEFAULT_GRAPHCUT_WEIGHT_SCALE: int
