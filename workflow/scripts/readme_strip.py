"""README's picture strip: Cook & Torrance's copper vase (Fig. 6b), a row of their Fig. 7 vases,
and under them copper's exact colour against the angle of incidence (Fig. 5b's continuous strip,
0 to 90 degrees from left to right), in the display space of config ``colour.space`` as its
parts are, and tagged with it."""

import numpy as np
import pandas as pd
from PIL import Image

from reflectance.colour.display import display_tag
from reflectance.io.images import write_png
from reflectance.scripting import script_log

with script_log(snakemake) as log:
    cfg = snakemake.params.strip
    height, gap = cfg["height_px"], cfg["gap_px"]
    tiles = []
    for path in [snakemake.input.vase, *snakemake.input.vases]:
        with Image.open(path) as im:
            im = im.convert("RGB")
            width = round(im.width * height / im.height)
            tiles.append(np.asarray(im.resize((width, height), Image.LANCZOS), dtype=np.float64))
    total = sum(t.shape[1] for t in tiles) + gap * (len(tiles) - 1)
    canvas = np.zeros((height + gap + cfg["colour_strip_px"], total, 3))
    x = 0
    for tile in tiles:
        canvas[:height, x:x + tile.shape[1]] = tile / 255.0
        x += tile.shape[1] + gap

    # the colour strip: each column the exact colour of the nearest computed angle (display RGB as
    # the Fig. 5 script encoded it), on a proportional angle axis
    strip = pd.read_csv(snakemake.input.colours)
    exact = strip[strip.method == "exact"].sort_values("angle_deg")
    angles = (np.arange(total) + 0.5) / total * 90.0
    nearest = np.abs(angles[:, None] - exact.angle_deg.to_numpy()[None, :]).argmin(axis=1)
    canvas[height + gap:] = exact[["R", "G", "B"]].to_numpy()[nearest][None, :, :]
    write_png(snakemake.output.png, canvas, tag=display_tag(snakemake.params.space))  # as its parts
    log.info("strip %d x %d px: %d renders and copper's colour from 0 to 90 degrees",
             total, canvas.shape[0], len(tiles))
