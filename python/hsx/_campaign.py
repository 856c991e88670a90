"""Campaigns from Python: hsx.campaign, an iterator of per-scene records (hsx.CampaignRecord) in index order, run by
the library's campaign runner (algorithms/campaign/campaign.hpp, the engine of `hsx campaign`), and
hsx.campaign_checks, the catalogue of the checks."""
from __future__ import annotations

import dataclasses
from typing import Dict, List, Optional, Sequence, Tuple, Union

from . import _hsx
from ._scene import Scene

# `hsx campaign`'s default for --samples (up to 6 samples per scene), which hsx.campaign keeps; hsx.random_scene's
# default is geometry/random_scene.hpp's (no samples).
CAMPAIGN_MAX_SAMPLES = 6

@dataclasses.dataclass(frozen=True)
class CampaignRecord:
    """What became of scene ``index`` of a campaign of seed ``seed``: the fields of a line of `hsx campaign --out`'s
    results.jsonl. ``outcome`` is "checked", "refused" (the arrangement limits refused it; ``note`` says which) or
    "error" (the library threw on it: a bug; ``note`` has the message). ``checks`` maps each selected check, in
    catalogue order, to (status, witness), status one of "held", "failed", "skipped", "stopped". ``timed_out``: the
    scene reached the campaign's time limit. ``failed``: some check failed or the outcome is "error"."""
    index: int
    seed: int
    halfspaces: int
    cells: int
    patches: int
    samples: int
    degeneracies: List[str]
    outcome: str
    note: str
    timed_out: bool
    checks: Dict[str, Tuple[str, str]]
    failed: bool
    intended: List[int] = dataclasses.field(default_factory=list)
    _scene_json: Optional[str] = dataclasses.field(default=None, repr=False, compare=False)
    _settings: dict = dataclasses.field(default_factory=dict, repr=False, compare=False)

    def scene(self) -> Scene:
        """The scene as an hsx.Scene: the one the campaign kept when the scene failed, otherwise generated again
        (hsx.random_scene(seed, index, **settings): the same scene, the generator being deterministic). Its
        ``degeneracies`` lists the patterns applied."""
        if self._scene_json is not None:
            text = self._scene_json
        elif self._settings.get("sample_policy", "uniform") == "intended":
            generator = {k: v for k, v in self._settings.items() if k != "sample_policy"}
            text = _hsx._campaign_scene(self.seed, self.index, "", {"sample_policy": "intended"}, generator)
        else:
            from . import random_scene
            settings = {k: v for k, v in self._settings.items() if k != "sample_policy"}
            return random_scene(self.seed, self.index, **settings)
        scene = Scene.from_json(text, source=f"<campaign scene {self.seed}/{self.index}>")
        scene.degeneracies = list(self.degeneracies)
        return scene

    def to_json(self) -> dict:
        """The record as `hsx campaign --out`'s results.jsonl writes it (io/campaign_files.hpp record_to_json):
        "note" only when not empty, "timed_out" only when true."""
        j = {"index": self.index, "seed": self.seed, "halfspaces": self.halfspaces, "cells": self.cells,
             "patches": self.patches, "samples": self.samples, "degeneracies": list(self.degeneracies),
             "outcome": self.outcome}
        if self.note:
            j["note"] = self.note
        if self.timed_out:
            j["timed_out"] = True
        if self.intended:
            j["intended"] = list(self.intended)
        j["checks"] = [{"check": name, "status": status, "witness": witness}
                       for name, (status, witness) in self.checks.items()]
        return j


class Campaign:
    """The iterator hsx.campaign returns: the records in index order, computed ahead on ``jobs`` threads (at most
    about 4 x jobs records wait to be read). ``close()`` (or leaving a ``with`` block, or dropping it) stops the
    campaign once the scenes being run finish; Ctrl-C while waiting for a record does the same and raises
    KeyboardInterrupt."""

    def __init__(self, run, settings: dict):
        self._run = run
        self._settings = settings

    def __iter__(self) -> "Campaign":
        return self

    def __next__(self) -> CampaignRecord:
        try:
            d = next(self._run)
        except KeyboardInterrupt:
            self._run.close()  # the C++ side stopped already when the interrupt came while it waited
            raise
        return CampaignRecord(index=d["index"], seed=d["seed"], halfspaces=d["halfspaces"], cells=d["cells"],
                              patches=d["patches"], samples=d["samples"], degeneracies=list(d["degeneracies"]),
                              outcome=d["outcome"], note=d["note"], timed_out=d["timed_out"],
                              checks={name: (status, witness) for name, status, witness in d["checks"]},
                              failed=d["failed"], intended=list(d["intended"]), _scene_json=d["scene_json"],
                              _settings=dict(self._settings))

    def close(self) -> None:
        """Stops the campaign (waiting for the scenes being run); the iteration then ends."""
        self._run.close()

    def __enter__(self) -> "Campaign":
        return self

    def __exit__(self, *exc) -> None:
        self.close()


def campaign(seed: int, count: int, start: int = 0, checks: Union[None, str, Sequence[str]] = None, jobs: int = 1,
             time_limit: float = 0, *, max_labellings: Optional[int] = None, max_states: Optional[int] = None,
             max_graph_cuts: Optional[int] = None, precision: Optional[int] = None, max_cells: Optional[int] = None,
             max_side_table: Optional[int] = None, sample_policy: str = "uniform", **settings) -> Campaign:
    """Scenes ``start`` .. ``start + count - 1`` of seed ``seed`` (hsx.random_scene's scenes), each arranged and
    checked by the proposition checkers, as `hsx campaign --seed S --count N --start K` runs them: an iterator of
    hsx.CampaignRecord in index order, the same records for any ``jobs`` (threads), except where ``time_limit``
    (seconds per scene, 0: none) cuts scenes short.

    ``checks``: the checks to run, by name (hsx.campaign_checks()), as a list or a comma-separated string; None
    or "default": check_all's nine (`hsx campaign`'s default); "all": every check. Limits as `hsx campaign`'s options, None keeping its default: ``max_labellings``
    (--max-labellings), ``max_states``, ``max_graph_cuts`` (per search; 0: none), ``precision`` (bits of the
    certified comparisons), ``max_cells`` and ``max_side_table`` (the arrangement's; a scene beyond them is
    "refused"). ``sample_policy``: "uniform" (the generator's samples, up to max_samples on the boundaries) or
    "intended" (`hsx campaign --sample-policy intended`: the samples of a random orientation-preserving intended
    shape, one per boundary component; the record's ``intended`` lists its cells; max_samples and near_percent
    are not used). ``settings``: the generator's, as hsx.random_scene's keyword arguments, except that max_samples
    defaults to 6 as in `hsx campaign` (``hsx._campaign.CAMPAIGN_MAX_SAMPLES``; 0: scenes without samples).

    Bad settings raise hsx.InputError here, before any scene is run. The scenes run with the GIL released."""
    settings.setdefault("max_samples", CAMPAIGN_MAX_SAMPLES)
    if checks is None:
        check_list = ""
    elif isinstance(checks, str):
        check_list = checks
    else:
        check_list = ",".join(checks)
    options = {name: value for name, value in (("max_labellings", max_labellings), ("max_states", max_states),
                                               ("max_graph_cuts", max_graph_cuts), ("precision", precision),
                                               ("max_cells", max_cells), ("max_side_table", max_side_table))
               if value is not None}
    if count < 0:
        raise _hsx.InputError("count: must be >= 0")
    if start < 0:
        raise _hsx.InputError("start: must be >= 0")
    options["sample_policy"] = sample_policy
    run = _hsx._campaign(seed, start, count, check_list, jobs, time_limit, options, settings)
    return Campaign(run, dict(settings, sample_policy=sample_policy))


def campaign_checks() -> List[Tuple[str, str]]:
    """The checks a campaign can run, as (name, description) in catalogue order (`hsx campaign --list-checks`)."""
    return [tuple(c) for c in _hsx._campaign_checks()]
