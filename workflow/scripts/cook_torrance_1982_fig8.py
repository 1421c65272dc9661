"""Cook & Torrance 1982, Fig. 8: "A watch" (reflectance.geometry.watch), rendered spectrally under a single
light: gold case, bezel and outer band (links with a rougher interior than border), stainless-steel
inner band, a dark face and red LEDs of dominant wavelength 640 nm. Also tabulates each part's
material and what the image shows of it."""

from reflectance.papers.draw.ct82_fig8 import run
from reflectance.scripting import run_job

run_job(snakemake, run)
