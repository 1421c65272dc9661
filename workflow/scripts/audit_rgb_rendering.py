"""Audit 2, spectral versus RGB rendering: Cook & Torrance 1982's metal vases (Fig. 6b, Fig. 7)
rendered spectrally and as a three-channel RGB renderer would (F0 per display channel, Schlick per
channel); CIEDE2000 maps and statistics per metal."""

from pathlib import Path

import numpy as np
import pandas as pd
from matplotlib.colors import BoundaryNorm

from reflectance.render.rgb import display_exposure, render_spectral_and_rgb
from reflectance.colour.colorimetry import tristimulus_weights
from reflectance.colour.difference import dE2000_map, dE2000_statistics
from reflectance.colour.display import display_tag, XYZ_to_display, XYZ_to_linear_RGB
from reflectance.io.atomic import atomic_write
from reflectance.io.figures import new_figure, savefig
from reflectance.io.tables import write_csv
from reflectance.optics.spectra import load_material
from reflectance.papers.scenes import fig7_vases_CookTorrance1982, vase_scene_CookTorrance1982
from reflectance.render.scene import scene_from_dict
from reflectance.scripting import script_log, write_audit_metadata

BOUNDS = [0, 0.5, 1, 2, 5, 10, 20]  # colour bands of the maps (CIEDE2000)

with script_log(snakemake) as log:
    p, out = snakemake.params, snakemake.output
    cfg, fig6, colour_cfg = p.audit, p.fig6, p.colour
    spectra_dir = str(Path(snakemake.input.spectra[0]).parent)
    published = fig6["published"]
    # Fig. 7's metals with Fig. 6b's s, d and lobes (Cu: Fig. 6b itself)
    vases = {vase: material for vase, group, material in
             fig7_vases_CookTorrance1982(p.fig7, fig6, p.table1) if group == "metal"}
    metals, labels = list(vases), p.fig7["labels"]
    rows, shown = [], []
    for metal in metals:
        # Fig. 7's vase of this metal exactly as the default figure renders it, at the audit's size
        document = vase_scene_CookTorrance1982(fig6, vases[metal], published["ambient_reference"],
                                               p.wavelengths, colour_cfg, spectra_dir,
                                               cfg["image"], exposure=published["exposure"])
        scene = scene_from_dict(document, source=f"audits.rgb_rendering {metal}")
        # the metals share vase, camera and lights: traced once (keep_trace)
        spectral, rgb = render_spectral_and_rgb(scene, colour_cfg["space"], keep_trace=True)
        scale = display_exposure(spectral, scene)  # both shown as the spectral vase is
        W = tristimulus_weights(scene.wavelengths, colour_cfg["illuminant"], scene.observer)
        white = W.sum(axis=0)
        dE = dE2000_map(rgb, spectral, scale, white)
        vase = (spectral[..., 1] > 0) | (rgb[..., 1] > 0)
        F0_RGB = XYZ_to_linear_RGB(load_material(metal, scene.wavelengths, spectra_dir).F0 @ W,
                                   colour_cfg["space"], illuminant=white)
        brightest = np.unravel_index(np.argmax(spectral[..., 1]), dE.shape)
        stats = dE2000_statistics(dE, vase, cfg["percentile"])
        rows.append({"metal": metal, "label": labels.get(metal, metal), "pixels": int(vase.sum()),
                     **{f"dE2000_{k}": v for k, v in stats.items()},
                     "dE2000_brightest_pixel": float(dE[brightest]),
                     "F0_R": F0_RGB[0], "F0_G": F0_RGB[1], "F0_B": F0_RGB[2],
                     "F0_in_gamut": bool(np.all((F0_RGB >= 0) & (F0_RGB <= 1))),
                     "exposure_scale": scale})
        d = scene.display
        kwargs = dict(expose=False, illuminant=d.illuminant, observer=scene.observer,
                      wavelengths=scene.wavelengths, highlight_knee=d.highlight_knee,
                      highlight_rolloff=d.highlight_rolloff)
        shown.append((metal, [XYZ_to_display(x * scale, d.space, d.gamut_clip, **kwargs)
                              for x in (spectral, rgb)], np.where(vase, dE, np.nan)))
        log.info("%s: %s", metal, rows[-1])
    table = pd.DataFrame(rows)
    table.pipe(write_csv, out.csv, float_format="%.6g")
    write_audit_metadata(
        snakemake, "Audit 2, spectral versus RGB rendering: Cook & Torrance 1982's metal vases "
        "rendered spectrally and per display channel; CIEDE2000 per object pixel",
        illuminant=colour_cfg["illuminant"], observer=colour_cfg["observer"],
        wavelengths_nm=p.wavelengths, space=colour_cfg["space"],
        units={"metal": "text", "label": "text", "pixels": "pixels", "dE2000_*": "CIEDE2000",
               "F0_R": "1 (linear display RGB)", "F0_G": "1 (linear display RGB)",
               "F0_B": "1 (linear display RGB)", "F0_in_gamut": "text (True/False)",
               "exposure_scale": "1 (XYZ multiplier)"})

    n = len(shown)
    fig = new_figure(1.15 * n + 0.9, 4.9, facecolor="white")
    axes = fig.subplots(3, n, gridspec_kw={"left": 0.1, "right": 0.86, "top": 0.9,
                                           "bottom": 0.02, "wspace": 0.04, "hspace": 0.06})
    norm = BoundaryNorm(BOUNDS, 256, extend="max")
    for j, (metal, (spectral_rgb, rgb_rgb), dE) in enumerate(shown):
        axes[0, j].imshow(spectral_rgb, interpolation="nearest")
        axes[1, j].imshow(rgb_rgb, interpolation="nearest")
        axes[2, j].set_facecolor("black")
        image = axes[2, j].imshow(dE, cmap="magma_r", norm=norm, interpolation="nearest")
        axes[0, j].set_title(labels.get(metal, metal), fontsize=8)
        for ax in axes[:, j]:
            ax.set_xticks([]), ax.set_yticks([])
            ax.set_facecolor("black")
    for ax, name in zip(axes[:, 0], ("spectral\n(F per \u03bb)", "RGB renderer\n(Schlick on F0 RGB)",
                                      "\u0394E00")):
        ax.set_ylabel(name, fontsize=8)
    bar = fig.colorbar(image, cax=fig.add_axes((0.88, 0.04, 0.02, 0.26)), ticks=BOUNDS,
                       format="%g")
    bar.set_label("CIEDE2000", fontsize=8)
    bar.ax.tick_params(labelsize=7)
    fig.suptitle("Cook & Torrance 1982, Figs. 6b and 7: metal vases, spectral against RGB "
                 "rendering", fontsize=9)
    savefig(fig, out.png, out.pdf, tight=False, tag=display_tag(colour_cfg["space"]))

    worst = table.loc[table.dE2000_max.idxmax()]
    pkey = f"dE2000_p{cfg['percentile']:g}"
    parts = "; ".join(f"{r.label} {r.dE2000_mean:.2f} / {getattr(r, pkey):.2f} / {r.dE2000_max:.2f}"
                      for r in table.itertuples(index=False))
    answer = (f"**Answer:** the RGB renderer's vases lie a mean CIEDE2000 of "
              f"{table.dE2000_mean.min():.2f} to {table.dE2000_mean.max():.2f} from the spectral "
              f"ones, up to {worst.dE2000_max:.1f} ({worst.label}); per metal (mean / "
              f"{cfg['percentile']:g}th percentile / max): {parts}.\n")
    # V.H depends on L and V only: for a directional light and a distant camera, one value per light
    camera = fig6["camera"]
    V = np.subtract(camera["position"], camera["look_at"])
    V = V / np.linalg.norm(V)
    VH = []
    for light in fig6["lights"]:
        L = np.asarray(light["direction"], float) / np.linalg.norm(light["direction"])
        VH.append(float(V @ ((L + V) / np.linalg.norm(L + V))))
    answer += (f"At the vase's centre V.H = {', '.join(f'{c:.3f}' for c in VH)} for the two "
               f"lights, where (1 - V.H)^5 <= {max((1 - c) ** 5 for c in VH):.1e}.\n")
    with atomic_write(out.answer) as tmp:
        Path(tmp).write_text(answer)
    log.info("%s", answer.strip())
