"""Cook & Torrance 1982, Fig. 6: (a) a copper-coloured plastic vase, (b) a copper vase, rendered
spectrally (reflectance.render.pipeline) with the paper's parameters. The ambient term is read as
printed or as 1 % of the lights' irradiance (each reading of ``params.readings``, one exposure at the
brightest colour), or, for the default figure (``params.published``), with the object metered and
its highlights compressed at constant chromaticity, and Fig. 6a's labelled departure beside the
printed panel. Also tabulates the size of the ambient term and how each panel reads. One process
makes every variant (the default figure, then each reading; outputs named ``<reading>_<name>``):
they share the imports and, where their geometry, camera and lights agree (tracing.trace_key), the
trace."""

from reflectance.papers.draw.ct82_fig6 import run
from reflectance.scripting import run_job

run_job(snakemake, run)
