"""Blinn 1977, Fig. 7 as a light sweep, drawn: the job of rule ``blinn77_fig7_sweep``, called by
its script, ``workflow/scripts/blinn_1977_fig7_sweep.py`` (which says what the figure shows).
What the job reads, renders and writes is declared in
:mod:`reflectance.papers.figures.blinn77_fig7_sweep`."""

from __future__ import annotations

import dataclasses
import logging
from typing import Any

import numpy as np
import pandas as pd
from matplotlib.patches import Rectangle
from PIL import Image, ImageDraw, ImageFont

from reflectance.colour.display import compress_highlights, display_tag, encode
from reflectance.io.atomic import atomic_write
from reflectance.io.captions import write_caption_values
from reflectance.io.figures import OKABE_ITO, PRINT_WIDTH_IN, TEXT_SIZE, new_figure, savefig
from reflectance.render.integrator import shade_samples
from reflectance.render.scene import scene_from_dict
from reflectance.papers.figures import blinn77_fig7_sweep as definition
from reflectance.papers.scenes import (highlight_crossover_Blinn1977, mirror_highlight_Blinn1977,
                                       sweep_camera_Blinn1977)
from reflectance.scripting import params_dict
from reflectance.render.shadows import shadow_masks
from reflectance.render.visibility import visibility
from reflectance.io.tables import write_csv

MODELS = {"phong": "Phong", "torrance_sparrow": "Torrance-Sparrow"}

__all__ = ["run"]


def _contact_picks(angles, n, crossover):
    """The contact sheet's frames (indices into ``angles``): ``n`` evenly spaced, first and last
    among them, one of them traded for the last frame before the ``crossover`` angle (None: none),
    so that the sheet shows aluminium's highlight still the brighter just before it."""
    picks = np.round(np.linspace(0, len(angles) - 1, max(n - (crossover is not None), 2)))
    before = [i for i, a in enumerate(angles) if crossover is not None and a < crossover]
    return np.unique(np.append(picks.astype(int), before[-1:]))


def run(snakemake: Any, log: logging.Logger) -> None:
    """Shade every frame of the light sweep from one trace, write the GIF, the table and the
    contact sheet and the caption's value: ``snakemake`` is the rule's job (its params and
    output), ``log`` its log."""
    params = params_dict(snakemake.params)
    cfg, fig7, out = params["sweep"], params["fig7"], snakemake.output
    panels = [fig7["panels"][key] for key in cfg["panels"]]
    cam = sweep_camera_Blinn1977(definition.seen(params), cfg)
    angles = np.linspace(*cfg["angles_deg"], cfg["n_frames"])
    scenes = {}
    for item in definition.scenes(params):  # the scenes the config check validated
        scenes[item.tags["panel"], item.tags["model"]] = scene_from_dict(
            item.document, source=f"{item.source} (panel {item.tags['panel']}, "
                                  f"{item.tags['model']})")
    first = next(iter(scenes.values()))
    samples = visibility(first.mesh, first.camera)  # the same object and camera in every frame
    shadowed = shadow_masks(samples, first.mesh, [light.source for light in first.lights])
    crossover = (highlight_crossover_Blinn1977(fig7["panels"]["a"], fig7["panels"]["b"])
                 if len(panels) == 2 else None)
    font = ImageFont.load_default(size=13)
    frames, rows, greys, labels = [], [], {}, []  # greys: the frame's images without text, for the contact sheet
    brightest: dict[int, tuple[int, int]] = {}  # per frame, (row, column) of the brightest Torrance-Sparrow pixel of either material
    h, w = cam["height"], cam["width"]
    label_w, head, foot, gap = 96, 20, 22, 4
    for f, angle in enumerate(angles):
        canvas = Image.new("L", (label_w + 2 * w + gap, head + len(panels) * (h + gap) + foot), 0)
        draw = ImageDraw.Draw(canvas)
        for k, name in enumerate(MODELS.values()):
            draw.text((label_w + k * (w + gap) + w / 2, 3), name, fill=255, font=font, anchor="ma")
        # shade the frame's four images first: they share one exposure (white = the frame's
        # brightest i), compressed above fig7_sweep.highlight_knee, so materials and models
        # compare fairly and no highlight clips
        Y = {}
        for key in cfg["panels"]:
            for model in MODELS:
                scene = scenes[key, model]
                one = dataclasses.replace(scene, lights=(scene.lights[f],))
                Y[key, model] = samples.to_pixels(shade_samples(one, samples, shadowed[f:f + 1]))[..., 1]
        white = max(y.max() for y in Y.values())
        ts_top = np.max([Y[key, "torrance_sparrow"] for key in cfg["panels"]], axis=0)
        top_row, top_column = np.unravel_index(np.argmax(ts_top), ts_top.shape)
        brightest[f] = int(top_row), int(top_column)
        for r, (key, p) in enumerate(zip(cfg["panels"], panels)):
            for k, model in enumerate(MODELS):
                grey = encode(compress_highlights(np.repeat(Y[key, model][..., None], 3, -1) / white,
                                                  cfg["highlight_knee"]), first.display.space)
                image = np.round(255 * grey[..., 1]).astype(np.uint8)  # grey: R = G = B
                canvas.paste(Image.fromarray(image), (label_w + k * (w + gap), head + r * (h + gap)))
                greys[f, key, model] = image
            draw.text((label_w - 6, head + r * (h + gap) + h / 2), p["label"].replace(" ", "\n", 1),
                      fill=255, font=font, anchor="rm", align="right")
            phong, ts = Y[key, "phong"], Y[key, "torrance_sparrow"]
            diff, lit = np.abs(phong - ts), phong > 0
            rows.append({"frame": f, "panel": key, "label": p["label"], "light_angle_deg": angle,
                         "phong_max": phong.max(), "torrance_sparrow_max": ts.max(),
                         "max_abs_difference": diff.max(), "mean_abs_difference": diff[lit].mean(),
                         "frame_white": white,
                         # Blinn's p_s D3 G F / (N.E) where N = H (D3 = G = 1): the brightest highlight
                         "mirror_highlight": float(mirror_highlight_Blinn1977(p["p_s"], p["n"], angle))})
        label = _claim(rows[-len(panels):], angle, crossover)
        draw.text((label_w + w + gap / 2, canvas.size[1] - 3),
                  f"light {angle:5.1f}\u00b0 from the eye{label and '  ' + label}", fill=230,
                  font=font, anchor="md")
        labels.append(label)
        frames.append(canvas)
    with atomic_write(out.gif) as tmp:
        frames[0].save(tmp, format="GIF", save_all=True, append_images=frames[1:],
                       duration=cfg["frame_ms"], loop=0, optimize=False)
    table = pd.DataFrame(rows)
    if crossover is not None:  # the MgO/aluminium ratio of the mirror-point highlights
        ratio = (table[table.panel == "b"].mirror_highlight.to_numpy()
                 / table[table.panel == "a"].mirror_highlight.to_numpy())
        table["mirror_highlight_ratio_b_to_a"] = np.repeat(ratio, len(panels))
        table["crossover_deg"] = crossover
        log.info("MgO/aluminium mirror highlights cross at %.4f degrees from the eye", crossover)
    table.pipe(write_csv, out.csv, float_format="%.6g")
    log.info("%d frames of %s; %s", len(frames), frames[0].size, table.to_string())

    # The contact sheet drawn at the print width (its text at the figures' sizes, not the GIF's
    # pixel font): a block of frames per light angle, the renders pixel for pixel at DPI.
    picks = _contact_picks(angles, cfg["contact_frames"], crossover)
    cols, T = int(np.ceil(len(picks) / 2)), TEXT_SIZE
    label_in, gap, block_gap, top, head = 0.75, 0.03, 0.12, 0.5, 0.42  # inches
    DPI = 2 * w * cols / (PRINT_WIDTH_IN - label_in - (cols - 1) * block_gap - cols * gap)
    wi, hi = w / DPI, h / DPI
    bw = 2 * wi + gap  # a block: Phong and Torrance-Sparrow side by side
    W = label_in + cols * bw + (cols - 1) * block_gap
    # past the computed crossover the torus's lit rim (view fig7) is about a pixel thick: the last
    # frame's Torrance-Sparrow rim magnified in a strip below (fig7_sweep.rim_closeup pixels around the
    # frame's brightest Torrance-Sparrow pixel, the same crop of each material)
    last = picks[-1]
    closeup = crossover is not None and angles[last] > crossover and cfg["view"] == "fig7"
    cw, ch = min(cfg["rim_closeup"]["width_px"], w), min(cfg["rim_closeup"]["height_px"], h)
    zw = (W - label_in - (len(panels) - 1) * block_gap) / len(panels)  # inches per close-up
    zh, z_head = zw * ch / cw, 0.5
    H = top + 2 * (head + len(panels) * (hi + gap)) + 0.05 + (z_head + zh + 0.1) * closeup
    fig = new_figure(W, H, facecolor="black")
    for n, f in enumerate(picks):
        c, r = n % cols, n // cols
        x0, y_top = label_in + c * (bw + block_gap), H - top - r * (head + len(panels) * (hi + gap))
        # the frame lit as the default Fig. 7's edge-lit images are (same object, eye and light)
        as_fig7 = cfg["view"] == "grazing" and (
            (angles[f], cfg["azimuth_deg"]) == (fig7["grazing"]["light"]["angle_deg"],
                                                fig7["grazing"]["light"]["azimuth_deg"]))
        fig.text((x0 + bw / 2) / W, (y_top - 0.02) / H, f"light {angles[f]:.0f}\u00b0"
                 + (" (Fig. 7's)" if as_fig7 else "")
                 + (labels[f] and ": " + labels[f]), ha="center", va="top", color="white",
                 fontsize=T["symbol"])
        for k, (model, name) in enumerate(MODELS.items()):
            fig.text((x0 + k * (wi + gap) + wi / 2) / W, (y_top - head + 0.03) / H, name,
                     ha="center", va="bottom", color="0.85", fontsize=T["annotation"])
            for j, key in enumerate(cfg["panels"]):
                y = y_top - head - (j + 1) * (hi + gap) + gap
                ax = fig.add_axes(((x0 + k * (wi + gap)) / W, y / H, wi / W, hi / H))
                ax.imshow(greys[f, key, model], cmap="gray", vmin=0, vmax=255,
                          interpolation="nearest")
                ax.set_axis_off()
                if closeup and f == last and model == "torrance_sparrow":  # the crop, boxed
                    r0, c0 = _crop_origin(brightest[f], (h, w), (ch, cw))
                    ax.add_patch(Rectangle((c0 - 0.5, r0 - 0.5), cw, ch, fill=False,
                                           edgecolor=OKABE_ITO[1], lw=0.8))
                if c == 0 and k == 0:
                    fig.text((label_in - 0.06) / W, (y + hi / 2) / H,
                             panels[j]["label"].replace(" ", "\n", 1), ha="right", va="center",
                             color="white", fontsize=T["annotation"])
    values = {}
    if closeup:
        r0, c0 = _crop_origin(brightest[last], (h, w), (ch, cw))
        magnification = (zw / cw) / (wi / w)  # inches per pixel, against the sheet's renders
        y = 0.08
        fig.text((label_in + (W - label_in) / 2) / W, (y + zh + z_head - 0.04) / H,
                 f"light {angles[last]:.0f}\u00b0, Torrance-Sparrow: the lit rim in the boxes "
                 f"({cw} \u00d7 {ch} pixels), magnified {magnification:.0f} times, same exposure",
                 ha="center", va="top", color="white", fontsize=T["annotation"])
        for j, key in enumerate(cfg["panels"]):
            x = label_in + j * (zw + block_gap)
            ax = fig.add_axes((x / W, y / H, zw / W, zh / H))
            ax.imshow(greys[last, key, "torrance_sparrow"][r0:r0 + ch, c0:c0 + cw], cmap="gray",
                      vmin=0, vmax=255, interpolation="nearest", aspect="auto")
            ax.set_xticks([]), ax.set_yticks([])
            for side in ax.spines.values():  # boxed like the crops on the sheet
                side.set(visible=True, color=OKABE_ITO[1])
            row = table[(table.frame == last) & (table.panel == key)].iloc[0]
            ax.set_title(f"{panels[j]['label']}: brightest i {row.torrance_sparrow_max:.2f}",
                         color="white", fontsize=T["annotation"], pad=3)
        values = {"closeup_angle": f"{angles[last]:.0f}",
                  "closeup_magnification": f"{magnification:.0f}",
                  "closeup_rows": f"{r0} to {r0 + ch - 1}", "closeup_columns": f"{c0} to {c0 + cw - 1}"}
    cross = "" if crossover is None else (f";\nMgO's highlight passes aluminium's beyond "
                                          f"{crossover:.1f}\u00b0 from the eye")
    fig.suptitle(f"Blinn 1977, Fig. 7 as a movie (Phong p_s {cfg['phong_specular'].replace('_', ' ')})"
                 f"{cross}", y=1 - 0.04 / H, va="top", color="white", linespacing=1.3)
    savefig(fig, out.contact, dpi=DPI, tight=False, tag=display_tag(first.display.space))

    # the caption's number (workflow/report/blinn77_fig7_sweep.rst), from the table as written
    written = pd.read_csv(out.csv)
    # the frames where MgO's rendered Torrance-Sparrow peak is above aluminium's
    brighter = (written[written.panel == "b"].torrance_sparrow_max.to_numpy()
                > written[written.panel == "a"].torrance_sparrow_max.to_numpy())
    angle = written[written.panel == "a"].light_angle_deg.to_numpy()
    write_caption_values(out.values, {
        "crossover": f"{written.crossover_deg.iloc[0]:.1f}",
        "rendered_mgo_brighter": ", ".join(f"{a:.0f}" for a in angle[brighter]) or "none",
        "closeup": (f"Below the sheet, the {values['closeup_angle']}-degree frame's Torrance-Sparrow "
                    f"images are magnified {values['closeup_magnification']} times in the boxed "
                    f"{cw} by {ch} pixels "
                    f"(rows {values['closeup_rows']}, columns {values['closeup_columns']} of each "
                    f"render) around the frame's brightest Torrance-Sparrow pixel, the rim where "
                    f"N = H, each titled with its brightest i.") if values else
                   "No rim close-up is drawn: the view is not the torus, or no frame shown lies "
                   "past the crossover."})


def _crop_origin(centre: tuple[int, int], shape: tuple[int, int],
                 size: tuple[int, int]) -> tuple[int, int]:
    """The top-left pixel of a ``size`` (rows, columns) crop centred on ``centre`` and inside an
    image of ``shape``."""
    (r, c), (h, w), (sh, sw) = centre, shape, size
    return int(np.clip(r - sh // 2, 0, h - sh)), int(np.clip(c - sw // 2, 0, w - sw))


def _claim(rows: list[dict], angle: float, crossover: float | None) -> str:
    """The frame's label, true of its pixels: "MgO > Al" only where MgO's rendered
    Torrance-Sparrow peak exceeds aluminium's; past the computed crossover with aluminium's still
    the brighter render, that the mirror points are not resolved."""
    if crossover is None:
        return ""
    ts = {row["panel"]: row["torrance_sparrow_max"] for row in rows}
    if ts["b"] > ts["a"]:
        return "MgO > Al"
    return "MgO > Al at N = H, unresolved" if angle > crossover else ""
