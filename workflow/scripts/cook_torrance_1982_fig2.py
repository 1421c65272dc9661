"""Cook & Torrance 1982, Fig. 2, the geometry of reflection: N, L, V and H = (V + L)/|V + L| at
a point P, with alpha (N to H) and theta (V to H, and L to H) as arcs, as a pyvista scene."""

import numpy as np
import pandas as pd
import pyvista as pv

from reflectance.io.figures import OKABE_ITO, font_file, off_screen_plotter, save_plotter, text_colour
from reflectance.papers.polar import direction_from_angles
from reflectance.scripting import script_log
from reflectance.io.tables import write_csv

FONT = font_file()  # the figures' DejaVu Sans: it has the Greek letters VTK's own fonts lack
COLOURS = {"N": "black", "L": OKABE_ITO[4], "V": "#1f5fbf", "H": "#1f7a2e"}  # H: 5.4:1 on white


def direction(angles):
    return direction_from_angles(np.radians(angles["polar_deg"]), np.radians(angles["azimuth_deg"]))


def arc(a, b, radius, n=48):
    """Points on the great circle from unit vector a to unit vector b (slerp), at a radius."""
    omega = np.arccos(np.clip(a @ b, -1.0, 1.0))
    t = np.linspace(0.0, 1.0, n)[:, None]
    return radius * (np.sin((1 - t) * omega) * a + np.sin(t * omega) * b) / np.sin(omega)


with script_log(snakemake) as log:
    fig = snakemake.params.fig
    vectors = {"N": np.array([0.0, 0.0, 1.0]),
               "L": direction(fig["light"]), "V": direction(fig["viewer"])}
    half = vectors["V"] + vectors["L"]
    vectors["H"] = half / np.linalg.norm(half)  # C&T 1982: H = (V + L) / length(V + L)
    N, L, V, H = (vectors[k] for k in "NLVH")
    angles = {"alpha_deg": np.degrees(np.arccos(N @ H)),    # C&T 1982: alpha, N to H
              "theta_deg": np.degrees(np.arccos(V @ H)),    # theta, V to H ...
              "theta_L_deg": np.degrees(np.arccos(L @ H))}  # ... = L to H
    rows = [(f"{k}_{axis}", v[i]) for k, v in vectors.items() for i, axis in enumerate("xyz")]
    table = pd.DataFrame(rows + list(angles.items()), columns=["quantity", "value"])
    table.pipe(write_csv, snakemake.output.csv, float_format="%.6g")

    pl = off_screen_plotter(1400, 950)  # wide: the vectors fill it up to the title
    pl.set_background("white")
    pl.enable_anti_aliasing("ssaa")
    pl.add_mesh(pv.Plane(i_size=2.2, j_size=1.5, i_resolution=11, j_resolution=8),
                color="#e4dfd3", show_edges=True, edge_color="#c9c2b2")
    # N shorter than the theta arc from V to H, so that the arc passes over N's tip, not across it
    length = {"N": 0.8, "L": 1.15, "V": 1.15, "H": 1.15}
    for name, v in vectors.items():
        pl.add_mesh(pv.Arrow(start=(0, 0, 0), direction=v, tip_length=0.12, tip_radius=0.035,
                             shaft_radius=0.012, scale=length[name]), color=COLOURS[name])
    labels = {name: (length[name] + 0.1) * v for name, v in vectors.items()}
    # (from, to, radius, where along the arc the label sits)
    for text, (a, b, r, at) in {"\u03b1": (N, H, 0.38, 0.5), "\u03b8": (V, H, 0.97, 0.5),
                                "\u03b8 ": (L, H, 0.82, 0.5)}.items():
        points = arc(a, b, r)
        pl.add_mesh(pv.lines_from_points(points).tube(radius=0.006), color="#262626")
        mid = points[int(at * (len(points) - 1))]
        labels[text] = mid + 0.09 * mid / np.linalg.norm(mid)
    labels["P"] = np.array([0.05, -0.12, 0.0])
    labels["N"] = np.array([0.1, 0.0, 0.72])  # beside its tip, clear of the theta arc above it
    for text, p in labels.items():
        colour = COLOURS.get(text, "black")
        pl.add_point_labels(p[None, :], [text.strip()], font_size=34, font_file=FONT,
                            text_color=text_colour(colour), bold=False, show_points=False, shape=None,
                            always_visible=True, justification_horizontal="center",
                            justification_vertical="center")
    pl.add_text("Cook & Torrance 1982, Fig. 2 \u2014 the geometry of reflection\n"
                f"\u03b1 = {angles['alpha_deg']:.1f}\u00b0 (N to H),  "
                f"\u03b8 = {angles['theta_deg']:.1f}\u00b0 (V to H = L to H)",
                font_size=14, color="black", position="upper_left", font_file=FONT)
    pl.camera_position = [(-0.8, -5.0, 2.1), (0.0, 0.0, 0.3), (0.0, 0.0, 1.0)]  # the scene high, under the title
    pl.camera.zoom(1.2)
    save_plotter(pl, snakemake.output.png, margin=fig["margin_px"])
    log.info("L = %s, V = %s, H = %s; %s", L.round(4), V.round(4), H.round(4),
             {k: round(v, 3) for k, v in angles.items()})
