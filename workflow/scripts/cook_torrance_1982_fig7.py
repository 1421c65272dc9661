"""Cook & Torrance 1982, Fig. 7: "A variety of vases", six metals and six nonmetals with
"R_d = F0/pi", rendered one vase at a time (reflectance.render.pipeline) under Fig. 6's lighting and
composed into one grid. The default figure (``params.published``) exposes each row (metals,
nonmetals) once, metered on a white card facing the lights (config ``fig7.exposure``; the label gives
each vase's exposure relative to the first vase), so dark materials stay dark, with the labelled
per-vase factors of ``fig7.vase_exposure``; the readings of
the ambient term show the grid as ONE scene (one Cook & Torrance exposure). Plus labelled variants
(not in the paper) and a table of each vase's parameters, colour and how it reads. One process makes
every variant (the default figure, then each reading of ``params.readings``; outputs named
``<reading>_<name>``): they share the imports and the vases' trace (tracing.trace_key)."""

from reflectance.papers.draw.ct82_fig7 import run
from reflectance.scripting import run_job

run_job(snakemake, run)
