"""The snapshot panels of figures 5-7 of the paper (the pools as damage grows them, the paper's figures 5a, 6a-b and
7): each panel framed on its pools' current extent, true to scale, read from the runs' ``*_snapshots.npz``."""

from __future__ import annotations

import matplotlib
import matplotlib.pyplot as plt
import numpy as np
from mpl_toolkits.axes_grid1.anchored_artists import AnchoredSizeBar
from scipy.spatial import ConvexHull, QhullError

from .style import LAYER_COLOURS

SEEDED, CONVERTED = 1, 2  # history origin codes (sphgag.engine.history): a seeded GAG pool, tissue converted by damage
MATERIAL_COLOURS = {SEEDED: LAYER_COLOURS["GAG"], CONVERTED: "#2166ac"}
INTACT_GREYS = (0.84, 0.62)  # intact tissue: the innermost layer light, the outermost dark, the others between
DAMAGE_CMAP = matplotlib.colors.LinearSegmentedColormap.from_list("damage", ["#ffd300", "#f47b20", "#7f2704"])
MARGIN = 0.25  # a panel's margin around its pools: this fraction of their smaller extent (at least 1.5 spacings)
ASPECT = (0.25, 1.5)  # a panel's height over its width: no thinner strip, no taller column (the pools keep >= 10 %)
BALLOONED = "ballooned out of the wall: framed on the pool"


def intact_colours(layers) -> dict:
    """A grey per layer name of ``layers`` (``(name, outer radius)`` bands from the lumen out), lighter inside."""
    names = list(dict.fromkeys(name for name, _ in layers))
    greys = np.linspace(*INTACT_GREYS, len(names)) if len(names) > 1 else INTACT_GREYS[:1]
    return {name: f"{g:.2f}" for name, g in zip(names, greys)}


def read_snapshots(path) -> dict:
    """Every array of a ``*_snapshots.npz`` of rule delaminate, read into memory."""
    with np.load(path, allow_pickle=False) as data:
        return {name: data[name] for name in data.files}


def snapshot_indices(snap: dict, n: int) -> list:
    """``n`` snapshots spread evenly over a run, the first and the last included (fewer if the run has fewer)."""
    return sorted(set(np.linspace(0, len(snap["steps"]) - 1, n).round().astype(int).tolist()))


def spacing(snap: dict) -> float:
    """The run's particle spacing [um] (the median particle's side)."""
    return float(np.sqrt(np.median(snap["volume"])))


def local(snap: dict, k: int) -> np.ndarray:
    """Every particle of snapshot ``k`` in the pools' frame [um]: column 0 along the wall (circumferential), column 1
    radial, the origin at the centre of the pools' reference positions (a rotation: true to scale)."""
    pools = snap["s0_history_origin"] > 0
    X = snap["X"][pools]
    angle = np.arctan2(X[:, 1], X[:, 0]).mean()
    centre = np.hypot(X[:, 0], X[:, 1]).mean()
    c, s = np.cos(angle), np.sin(angle)
    x = snap[f"s{k}_x"]
    return np.column_stack([-x[:, 0] * s + x[:, 1] * c, x[:, 0] * c + x[:, 1] * s - centre])


def pool_area(points: np.ndarray, dx: float) -> float:
    """The area [um^2] a pool's particles (``points``) cover: the convex hull of their squares of side ``dx``."""
    corners = (points[:, None, :] + 0.5 * dx * np.array([[-1, -1], [-1, 1], [1, -1], [1, 1]])[None]).reshape(-1, 2)
    try:
        return float(ConvexHull(corners).volume)
    except QhullError:  # a single particle
        return dx * dx * len(points)


def ballooned(snap: dict, k: int) -> bool:
    """Whether a pool of snapshot ``k`` has swollen radially beyond the wall's (reference) thickness."""
    pools = snap[f"s{k}_history_origin"] > 0
    radial = local(snap, k)[pools, 1]
    R = np.hypot(*snap["X"].T)
    return bool(np.ptp(radial) > np.ptp(R))


def frame(snap: dict, k: int) -> tuple:
    """``(x0, x1, y0, y1)`` [um, the pools' frame :func:`local`]: the pools' current extent with a margin
    (:data:`MARGIN`), its height over width held within :data:`ASPECT` around the pools' centre."""
    dx = spacing(snap)
    p = local(snap, k)[snap[f"s{k}_history_origin"] > 0]
    lo, hi = p.min(axis=0) - 0.5 * dx, p.max(axis=0) + 0.5 * dx
    margin = max(1.5 * dx, MARGIN * float(np.min(hi - lo)))
    lo, hi = lo - margin, hi + margin
    (w, h), mid = hi - lo, 0.5 * (lo + hi)
    w, h = max(w, h / ASPECT[1]), max(h, ASPECT[0] * w)
    return mid[0] - w / 2, mid[0] + w / 2, mid[1] - h / 2, mid[1] + h / 2


def pool_fraction(snap: dict, k: int) -> float:
    """The fraction of the panel of snapshot ``k`` (:func:`frame`) its pools cover (each pool's :func:`pool_area`)."""
    x0, x1, y0, y1 = frame(snap, k)
    origin, pool = snap[f"s{k}_history_origin"], snap[f"s{k}_history_pool"]
    p, dx = local(snap, k), spacing(snap)
    area = sum(pool_area(p[(origin > 0) & (pool == n)], dx) for n in np.unique(pool[origin > 0]))
    return area / ((x1 - x0) * (y1 - y0))


def snapshot_status(snap: dict, k: int) -> str:
    """What damage has done by snapshot ``k``, in words."""
    origin, D = snap[f"s{k}_history_origin"], snap[f"s{k}_history_D"]
    converted = int(np.sum(origin == CONVERTED))
    d_max = float(D[origin == 0].max(initial=0.0))
    if converted:
        return f"{converted} converted to GAG"
    return f"max D {d_max:.2f}, none ruptured" if d_max > 0 else "no damage onset"


def scale_bar(ax, width_um: float):
    """A bar of a round length, about a quarter of the panel's width, with its length (lower right)."""
    length = float(10 ** np.floor(np.log10(0.3 * width_um)))
    length *= max((m for m in (1, 2, 5) if m * length <= 0.3 * width_um), default=1)
    small = matplotlib.font_manager.FontProperties(size=7)
    bar = AnchoredSizeBar(ax.transData, length, f"{length:g} um", "lower right", frameon=False, fontproperties=small)
    ax.add_artist(bar)


def snapshot_panel(ax, snap: dict, k: int, layers, title: str):
    """Snapshot ``k`` of a run in the pools' frame (:func:`local`, true to scale) framed on their current extent
    (:func:`frame`, with a scale bar): intact tissue grey by layer (``layers``: ``(name, outer radius)`` bands,
    :func:`intact_colours`: the media light, the adventitia dark), damaged tissue by D, seeded GAG red, GAG converted by
    damage blue; the title is ``title`` and the state (concentration, pass, what damage has done), and says so where
    the pool has ballooned out of the wall (:func:`ballooned`). Marker sizes are set by :func:`fit_particle_sizes`
    after the layout."""
    x0, x1, y0, y1 = frame(snap, k)
    dx = spacing(snap)
    p = local(snap, k)
    near = (p[:, 0] > x0 - dx) & (p[:, 0] < x1 + dx) & (p[:, 1] > y0 - dx) & (p[:, 1] < y1 + dx)
    near = np.flatnonzero(near)
    near = near[np.argsort(snap[f"s{k}_history_origin"][near] > 0, kind="stable")]  # the pools drawn over the tissue
    origin, D = snap[f"s{k}_history_origin"][near], snap[f"s{k}_history_D"][near]
    outer = [r for _, r in layers]
    band = np.minimum(np.searchsorted(outer, np.hypot(*snap["X"][near].T)), len(layers) - 1)
    grey = intact_colours(layers)
    colours = matplotlib.colors.to_rgba_array([grey[layers[b][0]] for b in band])
    damaged = (origin == 0) & (D > 0)
    colours[damaged] = DAMAGE_CMAP(D[damaged])
    for code in (SEEDED, CONVERTED):
        colours[origin == code] = matplotlib.colors.to_rgba(MATERIAL_COLOURS[code])
    edges = np.where(origin == CONVERTED, "k", np.where(damaged, matplotlib.colors.to_hex(DAMAGE_CMAP(1.0)), "none"))
    ax.scatter(*p[near].T, s=4, c=colours, edgecolors=edges, linewidths=np.where(edges == "none", 0.0, 0.7))
    ax._particle_spacing = dx
    ax.set(xlim=(x0, x1), ylim=(y0, y1), aspect="equal", xticks=[], yticks=[])
    scale_bar(ax, x1 - x0)
    state = f"c = {snap['concentrations'][k]:g} mEq/l, pass {int(snap['steps'][k])}: {snapshot_status(snap, k)}"
    note = f"\n{BALLOONED}" if ballooned(snap, k) else ""
    ax.set_title(f"{title}\n{state}{note}", fontsize=7, loc="left")


def snapshot_rows(fig, spec, rows, layers):
    """Snapshot panels in ``spec`` (a gridspec cell of ``fig``): ``rows`` is a list of lists of ``(snapshot, k,
    title)``, one list per row (a run, or a pool set), the states from left to right as in the paper's figures; each
    panel framed on its own pools (:func:`snapshot_panel`); the damage colour bar beside them."""
    n = max(len(row) for row in rows)
    grid = spec.subgridspec(len(rows), n + 1, width_ratios=[1.0] * n + [0.03])
    for i, row in enumerate(rows):
        for j, (snap, k, title) in enumerate(row):
            snapshot_panel(fig.add_subplot(grid[i, j]), snap, k, layers, title)
    damage_colourbar(fig, fig.add_subplot(grid[:, -1]))


def rows_height(rows, width: float) -> float:
    """The height [in] of the snapshot rows of a figure ``width`` in wide: each row as tall as its tallest panel (its
    frame's aspect), plus its titles."""
    n = max(len(row) for row in rows)
    tallest = [max((lambda f: (f[3] - f[2]) / (f[1] - f[0]))(frame(snap, k)) for snap, k, _ in row) for row in rows]
    return sum(0.85 * width / n * t + 0.75 for t in tallest)


def fit_particle_sizes(fig):
    """Draw the snapshot panels' particles one particle spacing wide, now that the layout is fixed."""
    fig.draw_without_rendering()
    for ax in fig.axes:
        if not hasattr(ax, "_particle_spacing"):
            continue
        lo, hi = ax.get_xlim()
        points_per_um = ax.get_window_extent().width * 72.0 / fig.dpi / (hi - lo)
        for coll in ax.collections:
            coll.set_sizes([(0.95 * ax._particle_spacing * points_per_um) ** 2])


def material_key(fig, layers):
    """The legend of the snapshot panels' colours, below the figure (``layers`` as :func:`snapshot_panel`)."""
    key = {name: (grey, f"intact {name}") for name, grey in intact_colours(layers).items()}
    key[SEEDED] = (MATERIAL_COLOURS[SEEDED], "seeded GAG pool")
    key[CONVERTED] = (MATERIAL_COLOURS[CONVERTED], "GAG converted by damage")
    handles = [
        plt.Line2D([], [], marker="s", ls="none", ms=7, color=colour, label=text) for colour, text in key.values()
    ]
    fig.legend(handles=handles, loc="outside lower center", ncols=len(handles), frameon=False)


def damage_colourbar(fig, cax):
    """The colour bar of the damage of the snapshot panels, in ``cax``."""
    bar = fig.colorbar(matplotlib.cm.ScalarMappable(matplotlib.colors.Normalize(0.0, 1.0), DAMAGE_CMAP), cax=cax)
    bar.set_label("damage D of tissue (eq. 2.28)")
