"""Blinn 1977, Fig. 7 as the movie Blinn says shows the differences best: the light swept from the
eye (front lit) to behind the object (edge lit), Phong and Torrance-Sparrow side by side, one row
per material (aluminium, MgO); an animated GIF (grey, i = 1 is white), a contact sheet of a few
frames and a table per frame and material, with the mirror-point highlights and their ratio.
Visibility is traced once; the shadows of every frame's light in one pass."""

from reflectance.papers.draw.blinn77_fig7_sweep import run
from reflectance.scripting import run_job

run_job(snakemake, run)
