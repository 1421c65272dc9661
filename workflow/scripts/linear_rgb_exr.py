"""A display-referred linear RGB OpenEXR beside a rendered XYZ one (colour.linear_rgb_exr):
channels R, G, B in the display's primaries with its chromaticities, exposed and gamut clipped as
the render's PNG, no transfer function; what most image viewers show as intended."""

from reflectance.render.pipeline import write_linear_RGB_from_XYZ
from reflectance.scripting import script_log

with script_log(snakemake) as log:
    write_linear_RGB_from_XYZ(snakemake.input.exr, snakemake.input.scene, snakemake.output[0])
    log.info("%s -> %s", snakemake.input.exr, snakemake.output[0])
