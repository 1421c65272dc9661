"""Cook & Torrance 1982, Fig. 7: "A variety of vases", six metals and six nonmetals with
"R_d = F0/pi", rendered one vase at a time (reflectance.render) under Fig. 6's lighting and
composed into one grid shown as ONE scene: one Cook & Torrance exposure for all vases. Plus
labelled extras (not in the paper) and a table of each vase's parameters and mean colour."""

from pathlib import Path

import numpy as np
import pandas as pd
import yaml

from reflectance.colorimetry import tristimulus_weights
from reflectance.display import XYZ_to_display, expose_CookTorrance1982
from reflectance.io import atomic_write
from reflectance.plotting import new_figure, savefig
from reflectance.render import render, write_render
from reflectance.scene import scene_from_dict
from reflectance.scripting import script_log
from reflectance.spectra import list_materials, load_material

GROUPS = {"metal": "six metals: Fig. 6b's s, d, D, F from measured n, k",
          "nonmetal": "six nonmetals: Table I's s, d, m", "extra": "extra, not in the paper"}
READINGS = {"intensity": "as printed, I_ia = {f} I_i",
            "irradiance": "{f} of the lights' irradiance, I_ia = {f} \u03a3 I_i d\u03c9_i / \u03c0"}


def nonmetal(row):
    """A Table I row as a scene material (R_d = F0/pi of the same material: the scene default)."""
    if row["m"] is None:  # Table I: m "Not used", which only s = 0 allows
        if row["s"] != 0:
            raise ValueError(f"config.yaml table1 {row['material']}: m is null but s = {row['s']}")
        # s = 0 leaves d R_d: the Lambertian F0/pi (the 'physical' Lambert BRDF is albedo/pi)
        return {"name": row["material"], "model": "Lambert", "convention": "physical",
                "s": 0.0, "d": row["d"]}
    return {"name": row["material"], "s": row["s"], "d": row["d"], "m": row["m"]}


def vases(fig, fig6, table1):
    """(id, group, scene material) of every vase: metals, then Table I, then the extras."""
    b = fig6["panels"]["b"]  # C&T 1982 Fig. 7: "the same parameters used for Figure 6b"
    out = [(e["material"], "metal", {"name": e["material"], "s": b["s"], "d": b["d"],
                                     "lobes": b["lobes"]}) for e in fig["metals"]]
    out += [(row["material"], "nonmetal", nonmetal(row)) for row in table1]
    rows = {row["material"]: row for row in table1}
    for i, extra in enumerate(fig["extras"]):
        if extra["table1"] not in rows:
            raise ValueError(f"config.yaml figures.cook_torrance_1982.fig7.extras[{i}].table1: "
                             f"{extra['table1']!r} is not a table1 row; known: {', '.join(rows)}")
        material = dict(nonmetal(rows[extra["table1"]]), diffuse_material=extra["diffuse_material"])
        out.append((f"{extra['table1']}_{extra['diffuse_material']}", "extra", material))
    return out


def scene_document(fig6, material, reference, size, wavelengths, colour, spectra_dir):
    """One vase alone, as Fig. 6 renders it (workflow/schemas/scene.schema.yaml)."""
    material = {"distribution": fig6["distribution"], "convention": fig6["convention"],
                "fresnel": fig6["fresnel"], "shadowing": fig6["shadowing"], **material}
    return {"wavelengths": dict(wavelengths), "observer": colour["observer"],
            "spectra_dir": spectra_dir, "spectral": fig6["spectral"],
            "camera": {**fig6["camera"], **size},
            "objects": [{"name": "vase", "geometry": {"type": "vase", **fig6["vase"]},
                         "material": material}],
            "lights": [{"type": "directional", **light} for light in fig6["lights"]],
            "ambient": {"fraction": fig6["ambient_fraction"], "reference": reference},
            "display": {"space": colour["space"], "gamut_clip": colour["gamut_clip"],
                        "illuminant": colour["illuminant"],
                        "png_bit_depth": colour["png_bit_depth"]}}


def label(material, sources):
    """Material(s) and where their spectra come from."""
    name, diffuse = material["name"], material.get("diffuse_material", material["name"])
    row = sources.loc[diffuse]
    kind = f"n, k: {row.dataset.rsplit('/', 1)[-1]}" if row.kind == "measured" else row.dataset
    return f"{name}\n{kind}" if diffuse == name else f"{name} F, {diffuse} R_d\n{kind}"


with script_log(snakemake) as log:
    p, out = snakemake.params, snakemake.output
    colour_cfg, reference = p.colour, p.reference
    spectra_dir = str(Path(snakemake.input.sources).parent)
    sources = list_materials(spectra_dir).set_index("material")
    rows, images, groups, labels = [], [], [], []
    for k, (vase, group, material) in enumerate(vases(p.fig, p.fig6, p.table1)):
        document = scene_document(p.fig6, material, reference, p.fig["vase_image"],
                                  p.wavelengths, colour_cfg, spectra_dir)
        scene = scene_from_dict(document,
                                source=f"config.yaml figures.cook_torrance_1982.fig7 {vase}")
        with atomic_write(out.scenes[k]) as tmp:
            Path(tmp).write_text(yaml.safe_dump(scene.document, sort_keys=False))
        result = render(scene)
        write_render(result, out.exrs[k])
        W = tristimulus_weights(scene.wavelengths, colour_cfg["illuminant"], scene.observer)
        F0 = load_material(material["name"], scene.wavelengths, spectra_dir).F0 @ W
        albedo = scene.objects[0].material.albedo @ W  # pi R_d (Cook & Torrance 1982: R_d = F0/pi)
        on = result.XYZ[..., 1] > 0
        mean = result.XYZ[on].mean(axis=0)
        rows.append({"vase": vase, "group": group, "material": material["name"],
                     "diffuse_material": material.get("diffuse_material", material["name"]),
                     "kind": sources.loc[material["name"], "kind"],
                     "model": scene.objects[0].material.model, "s": material["s"],
                     "d": material["d"], "m": material.get("m", np.nan),
                     "lobes": " ".join(f"{b['w']:g}x{b['m']:g}" for b in material.get("lobes", [])),
                     "ambient_reading": reference,
                     **{f"{name}_{c}": v for name, XYZ in (("F0", F0), ("albedo", albedo),
                                                           ("mean", mean))
                        for c, v in zip("XYZ", XYZ)},
                     "mean_x": mean[0] / mean.sum(), "mean_y": mean[1] / mean.sum(),
                     "Y_max": result.XYZ[..., 1].max(), "pixels": int(on.sum())})
        images.append(result.XYZ), groups.append(group), labels.append(label(material, sources))
        log.info("%s: %s; timings %s", vase, rows[-1], result.timings)

    # Cook & Torrance 1982: "all XYZ values in the scene are scaled equally": the grid is one scene
    display = dict(illuminant=colour_cfg["illuminant"], observer=colour_cfg["observer"],
                   wavelengths=scene.wavelengths)
    _, scale = expose_CookTorrance1982(np.stack(images), colour_cfg["space"], **display)
    pd.DataFrame(rows).assign(exposure_scale=scale).to_csv(
        out.csv, index=False, float_format="%.6g", lineterminator="\n")

    n_cols = max(groups.count("metal"), groups.count("nonmetal")) + ("extra" in groups)
    lit = np.flatnonzero(np.stack(images)[..., 1].max(axis=(0, 2)) > 0)  # rows any vase covers
    crop = slice(max(lit[0] - 4, 0), lit[-1] + 5)
    w, h = images[0].shape[1] / 100, (crop.stop - crop.start) / 100  # inches at dpi 100
    head, foot, top = 0.25, 0.4, 0.45
    fig_w, fig_h = n_cols * w * 1.04, top + 2 * (head + h + foot)
    fig = new_figure(fig_w, fig_h, facecolor="black")
    slots = {"metal": 0, "nonmetal": 0, "extra": n_cols - 1}  # extras in the last column
    first = {group: groups.index(group) for group in slots if group in groups}
    for i, (image, group, text) in enumerate(zip(images, groups, labels)):
        row, col = int(group != "metal"), slots[group]
        slots[group] += 1
        y0 = fig_h - top - row * (head + h + foot) - head
        ax = fig.add_axes((col / n_cols + 0.02 / n_cols, (y0 - h) / fig_h, w / fig_w, h / fig_h))
        ax.imshow(XYZ_to_display(image[crop] * scale, colour_cfg["space"],
                                 colour_cfg["gamut_clip"], expose=False, **display),
                  interpolation="nearest")
        ax.set_axis_off()
        ax.text(0.5, -0.01, text, transform=ax.transAxes, ha="center", va="top", color="white",
                fontsize=8, linespacing=1.15)
        if i == first[group]:  # the group's heading over its first vase
            fig.text(0.01 if group != "extra" else 1 - 0.5 / n_cols, (y0 + 0.07) / fig_h,
                     GROUPS[group], color="white" if group != "extra" else "#ffcc66",
                     fontsize=9 if group != "extra" else 8,
                     ha="left" if group != "extra" else "center")
    reading = READINGS[reference].format(f=f"{p.fig6['ambient_fraction']:g}")
    fig.suptitle(f"Cook & Torrance 1982, Fig. 7 \u2014 ambient {reading}; one exposure for "
                 "all vases", color="white", fontsize=10)
    savefig(fig, out.png, dpi=100)
