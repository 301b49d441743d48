"""Property-based fuzzing of the configuration validator (hypothesis).

Every mutation of a valid configuration has one of two outcomes: a clean
:class:`sphgag.config.ConfigError` that names the mutated key, or a
configuration that is still valid because the mutation kept it within the
documented ranges (then it builds its models: the geometry fits the wall).
Mutations: wrong types, NaN and infinities, values outside the ranges,
missing and unknown keys, pools moved outside the media.
"""

import copy
import math

import numpy as np
import yaml
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st

from sphgag import config
from sphgag.engine.loading import Load
from sphgag.engine.numerics import Numerics
from sphgag.studies import artery

from .conftest import ROOT, law_gag

SCHEMA = ROOT / "config" / "schema.yaml"
BASE = yaml.safe_load((ROOT / "config" / "ci.yaml").read_text())
TRIED = {"mutations": 0, "rejected": 0, "accepted": 0, "too_large": 0}


def eval_leaf(cfg, path):
    for k in path:
        cfg = cfg[k]
    return cfg


def leaves(node, path=()):
    """Paths of every scalar in the config."""
    if isinstance(node, dict):
        for k, v in node.items():
            yield from leaves(v, path + (k,))
    elif isinstance(node, list):
        for i, v in enumerate(node):
            yield from leaves(v, path + (i,))
    else:
        yield path


PATHS = sorted(leaves(BASE), key=str)
SCHEMA_DICT = config.schema(SCHEMA)
NUMBERS = [p for p in PATHS if not any("dx" in str(k) for k in p) and type(eval_leaf(BASE, p)) in (int, float)]
MAPPINGS = sorted({p[:-1] for p in PATHS if p and isinstance(p[-1], str)}, key=str)
ODD = st.one_of(
    st.just(float("nan")),
    st.just(float("inf")),
    st.just(-float("inf")),
    st.just("text"),
    st.just(None),
    st.just([1, 2]),
    st.just({"a": 1}),
    st.booleans(),
    st.integers(-(10**6), 10**6),
    st.floats(-1e9, 1e9, allow_nan=False),
)


def get(cfg, path):
    for k in path:
        cfg = cfg[k]
    return cfg


def dotted(path):
    out = ""
    for part in path:
        out += f"[{part}]" if isinstance(part, int) else (f".{part}" if out else str(part))
    return out


@st.composite
def mutation(draw):
    cfg = copy.deepcopy(BASE)
    kind = draw(st.sampled_from(["value", "in_range", "missing", "unknown", "pool"]))
    if kind == "in_range":  # a number anywhere in its documented range (particle spacings excepted: cost)
        path = draw(st.sampled_from(NUMBERS))
        node = config._subschema(SCHEMA_DICT, path)
        lo = node.get("minimum", node.get("exclusiveMinimum", 0.0))
        hi = node.get("maximum", node.get("exclusiveMaximum", 1e3))
        value = draw(st.floats(lo, hi, exclude_min="exclusiveMinimum" in node, exclude_max="exclusiveMaximum" in node))
        get(cfg, path[:-1])[path[-1]] = int(value) if isinstance(get(cfg, path), int) else value
    elif kind == "value":
        path = draw(st.sampled_from(PATHS))
        get(cfg, path[:-1])[path[-1]] = draw(ODD)
    elif kind == "missing":
        path = draw(st.sampled_from([p for p in PATHS if isinstance(p[-1], str)] + [(k,) for k in BASE]))
        del get(cfg, path[:-1])[path[-1]]
    elif kind == "unknown":
        parent = draw(st.sampled_from(MAPPINGS))
        path = parent + (draw(st.sampled_from(["colour", "dx", "tolerence", "Pools"])),)
        get(cfg, parent)[path[-1]] = 1.0
    else:  # a pool moved anywhere (possibly out of the media or onto a symmetry edge)
        path = ("swelling", "cases", "I")
        pool = get(cfg, path)
        pool["centre_radius_um"] = draw(st.floats(600.0, 700.0))
        pool["centre_angle_deg"] = draw(st.floats(0.5, 89.5))
        pool["angular_extent_deg"] = draw(st.floats(0.5, 30.0))
    return cfg, path


@settings(max_examples=300, deadline=None, derandomize=True, suppress_health_check=[HealthCheck.too_slow])
@given(mutation())
def test_a_mutated_config_is_rejected_by_name_or_really_valid(case):
    cfg, path = case
    TRIED["mutations"] += 1
    try:
        config.validate(cfg, SCHEMA)
    except config.ConfigError as exc:
        TRIED["rejected"] += 1
        message = str(exc)
        names = [dotted(path[:k]) for k in range(len(path), 0, -1)]
        assert any(n in message for n in names if n), (path, message)
        return
    TRIED["accepted"] += 1
    # still valid: every scalar is finite and typed, and the pools fit the media at this resolution
    for p in leaves(cfg):
        v = get(cfg, p)
        assert not (isinstance(v, float) and not math.isfinite(v)), p

    def particles(r_in, r_out, dx):
        return 0.25 * np.pi * (r_out**2 - r_in**2) / dx**2

    b, m = cfg["bilayer"], cfg["mean"]
    outer = b["inner_radius_um"] + sum(band["thickness_um"] for band in b["layers"])
    if (
        max(
            particles(b["inner_radius_um"], outer, b["dx_um"]),
            particles(m["inner_radius_um"], m["outer_radius_um"], m["dx_um"]),
        )
        > 20000
    ):
        TRIED["too_large"] += 1  # valid, but too big to build in a unit test
        return
    for case in cfg["swelling"]["cases"].values():  # each pool is its own run, under each charge law
        for law in cfg["gag"]["charge_laws"]:
            sector = artery.pool_sector(case)
            model = artery.bilayer_model(
                cfg["bilayer"], Numerics.of(cfg["numerics"]), pool=sector, gag=law_gag(cfg, law)
            )
            assert np.isfinite(model.props(Load(1.0, 10.0, material=(("transition", 1.0),)))).all()
    artery.mean_model(cfg["mean"], Numerics.of(cfg["numerics"]))


def teardown_module():
    print(
        f"\nconfig fuzz: {TRIED['mutations']} mutations, {TRIED['rejected']} rejected by name, "
        f"{TRIED['accepted']} accepted ({TRIED['too_large']} too large to build here, the rest built)"
    )
