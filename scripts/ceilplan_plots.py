"""Drawing shared by the figure scripts (plot-compare, plot-tour): CSV columns, routes coloured
by current over the map's top and side views, saving as PNG and SVG."""
import csv
import os

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
from matplotlib.collections import LineCollection  # noqa: E402


def read_columns(path):
    """Columns of a ceilplan CSV by name: numbers as floats (empty fields NaN), text columns
    such as path.csv's `phase` as strings; the leading `#` provenance comment is skipped."""
    with open(path, newline="") as f:
        rows = list(csv.DictReader(line for line in f if not line.startswith("#")))
    if not rows:
        return {}
    columns = {}
    for key in rows[0]:
        values = [r[key] for r in rows]
        try:
            columns[key] = [float(v) if v != "" else float("nan") for v in values]
        except ValueError:
            columns[key] = values
    return columns


def coloured_line(ax, xs, ys, values, norm, style, label):
    points = list(zip(xs, ys))
    segments = [[points[k], points[k + 1]] for k in range(len(points) - 1)]
    lines = LineCollection(segments, cmap="viridis", norm=norm, linewidths=2.5, linestyles=style, label=label)
    lines.set_array([0.5 * (values[k] + values[k + 1]) for k in range(len(values) - 1)])
    ax.add_collection(lines)
    ax.plot(xs[0], ys[0], "o", color="black", markersize=4)
    ax.plot(xs[-1], ys[-1], "s", color="black", markersize=4)
    return lines


def current_norm(paths):
    currents = [c for p in paths for c in p["current_a"]]
    return plt.Normalize(min(currents), max(currents))


def draw_map_views(directory, routes, title):
    """Top and side views of DIR/map_top.csv and DIR/map_side.csv with `routes`, a list of
    (path columns, line style, label), coloured by current. Returns the figure."""
    top = read_columns(os.path.join(directory, "map_top.csv"))
    side = read_columns(os.path.join(directory, "map_side.csv"))
    norm = current_norm([p for p, _, _ in routes])
    fig, (ax_top, ax_side) = plt.subplots(2, 1, figsize=(10, 10), constrained_layout=True)
    for ax, cells, (u, v), (u_label, v_label) in (
        (ax_top, top, ("x", "y"), ("x [m]", "y [m]")),
        (ax_side, side, ("x", "z"), ("x [m]", "z [m]")),
    ):
        if cells and "ceiling_m" in cells:
            low, high = min(cells["ceiling_m"]), max(cells["ceiling_m"])
            image = ax.scatter(cells["x_m"], cells["y_m"], c=cells["ceiling_m"], s=4, marker="s", cmap="Greys_r",
                               vmin=low - 0.5, vmax=high + 0.5 * (high - low) + 0.5, label="structure overhead")
            fig.colorbar(image, ax=ax, label="structure overhead at [m]", location="left")
        elif cells:
            ax.scatter(cells[f"{u}_m"], cells[f"{v}_m"], s=2, marker="s", color="0.75", label="structure")
        lines = None
        for p, style, label in routes:
            lines = coloured_line(ax, p[u], p[v], p["current_a"], norm, style, label)
        xs = [c for p, _, _ in routes for c in p[u]]
        ys = [c for p, _, _ in routes for c in p[v]]
        ax.set_xlim(min(xs) - 1.5, max(xs) + 1.5)
        ax.set_ylim(min(ys) - 1.5, max(ys) + 1.5)
        ax.set_aspect("equal")
        ax.set_xlabel(u_label)
        ax.set_ylabel(v_label)
        ax.legend(loc="upper right", fontsize=8)
        fig.colorbar(lines, ax=ax, label="current [A]")
    ax_top.set_title(title)
    ax_side.set_title("side view (structure within 1 m of the routes' y band)")
    return fig


def save(fig, out_dir, name):
    for extension in ("png", "svg"):
        fig.savefig(os.path.join(out_dir, f"{name}.{extension}"), dpi=150, bbox_inches="tight")
    plt.close(fig)
