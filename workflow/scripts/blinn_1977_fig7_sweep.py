"""Blinn 1977, Fig. 7 as the movie Blinn says shows the differences best: the light swept from the
eye (front lit) to behind the object (edge lit), Phong and Torrance-Sparrow side by side; an
animated GIF (grey, i = 1 is white), a contact sheet of a few frames and a table per frame.
Visibility is traced once; the shadows of every frame's light in one pass."""

import dataclasses

import numpy as np
import pandas as pd
from PIL import Image, ImageDraw, ImageFont

from reflectance.io.atomic import atomic_write
from reflectance.io.figures import new_figure, savefig
from reflectance.render.pipeline import RenderResult, display_image, shade_samples
from reflectance.render.scene import scene_from_dict
from reflectance.papers.scenes import blinn_scene_Blinn1977, materials_Blinn1977
from reflectance.scripting import script_log
from reflectance.render.shadows import shadow_masks
from reflectance.render.visibility import visibility

MODELS = {"phong": "Phong", "torrance_sparrow": "Torrance-Sparrow"}

with script_log(snakemake) as log:
    cfg, fig7, out = snakemake.params.sweep, snakemake.params.fig7, snakemake.output
    p = fig7["panels"][cfg["panel"]]
    m = materials_Blinn1977(p["p_s"], p["p_d"], p["c3"], p["n"], cfg["phong_specular"])
    cam = dict(fig7["camera"])
    cam.update(width=cfg["size"], height=round(cfg["size"] * cam["height"] / cam["width"]),
               supersample=cfg["supersample"])
    angles = np.linspace(*cfg["angles_deg"], cfg["n_frames"])
    lights = [{"angle_deg": a, "azimuth_deg": cfg["azimuth_deg"]} for a in angles]
    scenes = {model: scene_from_dict(
        blinn_scene_Blinn1977(fig7, m[model], lights, snakemake.params.wavelengths, cam),
        source=f"figures.blinn_1977.fig7_sweep ({model})") for model in MODELS}
    first = scenes["phong"]
    samples = visibility(first.mesh, first.camera)  # the same object and camera in every frame
    shadowed = shadow_masks(samples, first.mesh, [light.source for light in first.lights])
    font = ImageFont.load_default(size=12)
    frames, rows, sheet = [], [], []
    for f, angle in enumerate(angles):
        shown, Y = [], {}
        for model, scene in scenes.items():
            one = dataclasses.replace(scene, lights=(scene.lights[f],))
            XYZ = samples.to_pixels(shade_samples(one, samples, shadowed[f:f + 1]))
            rgb = display_image(RenderResult(XYZ, None, {}, {}, one))[0]
            shown.append(np.round(255 * rgb[..., 1]).astype(np.uint8))  # grey: R = G = B
            Y[model] = XYZ[..., 1]
        diff, lit = np.abs(Y["phong"] - Y["torrance_sparrow"]), Y["phong"] > 0
        rows.append({"frame": f, "light_angle_deg": angle, "phong_max": Y["phong"].max(),
                     "torrance_sparrow_max": Y["torrance_sparrow"].max(),
                     "max_abs_difference": diff.max(), "mean_abs_difference": diff[lit].mean()})
        h, w = shown[0].shape
        canvas = Image.new("L", (2 * w + 4, h + 36), 0)
        for k, (image, name) in enumerate(zip(shown, MODELS.values())):
            canvas.paste(Image.fromarray(image), (k * (w + 4), 18))
            ImageDraw.Draw(canvas).text((k * (w + 4) + w / 2, 2), name, fill=255, font=font,
                                        anchor="ma")
        ImageDraw.Draw(canvas).text((w + 2, h + 20), f"light {angle:5.1f}\u00b0 from the eye",
                                    fill=200, font=font, anchor="ma")
        frames.append(canvas)
    with atomic_write(out.gif) as tmp:
        frames[0].save(tmp, format="GIF", save_all=True, append_images=frames[1:],
                       duration=cfg["frame_ms"], loop=0, optimize=False)
    table = pd.DataFrame(rows)
    table.to_csv(out.csv, index=False, float_format="%.6g", lineterminator="\n")
    log.info("%d frames of %s; %s", len(frames), frames[0].size, table.to_string())

    picks = np.unique(np.round(np.linspace(0, len(frames) - 1, cfg["contact_frames"])).astype(int))
    cols = int(np.ceil(len(picks) / 2))
    w, h, gap, top = frames[0].size[0] / 100, frames[0].size[1] / 100, 0.1, 0.4  # inches
    W, H = cols * w + (cols + 1) * gap, 2 * h + 3 * gap + top
    fig = new_figure(W, H, facecolor="black")
    for k, f in enumerate(picks):
        x, y = gap + (k % cols) * (w + gap), gap + (1 - k // cols) * (h + gap)
        ax = fig.add_axes((x / W, y / H, w / W, h / H))
        ax.imshow(np.asarray(frames[f]), cmap="gray", vmin=0, vmax=255, interpolation="nearest")
        ax.set_axis_off()
    fig.suptitle(f"Blinn 1977, Fig. 7 as a movie: {p['label']} (p_s = {p['p_s']:g}, p_d = {p['p_d']:g}, "
                 f"n = {p['n']:g}, c3 = {p['c3']:g}; Phong p_s {cfg['phong_specular'].replace('_', ' ')}), "
                 f"frames {', '.join(str(f) for f in picks)}", fontsize=9.5, y=1 - 0.08 / H, va="top", color="white")
    savefig(fig, out.contact, dpi=100, tight=False)
