"""Wikipedia, "Specular highlight": the image "Specular highlights on a pair of spheres", rendered.
Two coloured plastic spheres (pigment reflectances recovered from Munsell notations; F of a
measured clear coat, so the highlights are white) with the article's Cook-Torrance model, one
directional light, a grey floor; beside them, in a panel of its own, the gold sphere of the
article's metals. Each panel has its exposure (config ``exposure``): Cook & Torrance's over both
would be set by the gold highlight and leave the plastics' highlights dim grey."""

from reflectance.papers.draw.article_spheres import run
from reflectance.scripting import run_job

run_job(snakemake, run)
