"""Captions state the build's numbers (issue 24): a caption template (workflow/report/*.rst) types
in only what the texts print and templates its parameters from ``snakemake.params``; every number
the workflow computes reaches it from the job's own results, through a values file of
reStructuredText substitutions (``reflectance.io.captions``) that the job writes from its table and
the caption includes.

The cheap checks read the templates and the scripts. The end-to-end one changes a parameter of
three figures in a copy of the session's build, rebuilds those figures, renders their captions in
Snakemake's report and checks each number they take from the job against the new tables.
"""

import ast
import html
import json
import re
import shutil
from pathlib import Path

import pytest
import yaml

ROOT = Path(__file__).resolve().parents[1]
REPORT = ROOT / "workflow" / "report"
SCRIPTS = ROOT / "workflow" / "scripts"
#: the rendered figures' drawings, each called by its script (reflectance.papers.draw)
DRAWINGS = ROOT / "workflow" / "reflectance" / "papers" / "draw"
#: the four texts, in ``shared/papers`` beside the project or beside a folder above it (a git
#: worktree sits deeper than the main checkout); not part of the project: skipped where absent
PAPERS = next((p / "shared" / "papers" for p in ROOT.parents if (p / "shared" / "papers").is_dir()),
              ROOT.parent / "shared" / "papers")

#: the decimals the captions quote from the texts, and where each text prints them
PRINTED = {
    "0.9196": "Wikipedia, Phong example: (-0.5196 - 0.4)^3 = 0.9196",
    "0.65": "Wikipedia, Phong example: 0.65^3",
    "0.133": "Wikipedia, Phong example: {0.133; 0.65; 0}",
    "0.274625": "Wikipedia, Phong example: 0.65^3 = 0.274625",
    "0.668": "Wikipedia, Phong example: ||H|| = 0.668",
    "0.940332": "Wikipedia, Phong example: 0.979701^3 = 0.940332",
    "0.2": "lecture, microfacet distributions: m near 0.2 ... nearly smooth",
    "0.6": "lecture, microfacet distributions: m near 0.6 ... rough",
    "605.767": "lecture: JHU course 605.767",
    "0.9": "lecture, Cook and Torrance: For shiny plastics: d = 0.9, s = 0.1",
    "0.1": "lecture, Cook and Torrance: For shiny plastics: d = 0.9, s = 0.1",
}

#: a decimal typed into a caption (not a section number such as §13.2)
DECIMAL = re.compile(r"(?<![\w.§])\d+\.\d+(?![\w.]*\d)")
#: a substitution reference |name| (reflectance.io.captions writes plain identifiers)
REFERENCE = re.compile(r"(?<![\w|])\|([A-Za-z]\w*)\|(?![\w|])")
INCLUDE = ".. include:: {{ snakemake.output.values }}"


def prose(template):
    """A caption template without its Jinja (templated from params) and its literals."""
    text = re.sub(r"\{\{.*?\}\}|\{%.*?%\}", " ", template, flags=re.S)
    return re.sub(r"``.*?``", " ", text, flags=re.S)


def typed_decimals(template):
    """The decimals a caption template types in that no text prints."""
    return [d for d in DECIMAL.findall(prose(template)) if d not in PRINTED]


def references(template):
    return set(REFERENCE.findall(prose(template)))


def scripts_named(template):
    """The scripts a caption names (each caption ends with its ``Code:``)."""
    return [SCRIPTS / f"{name}.py" for name in re.findall(r"workflow/scripts/(\w+)\.py", template)]


def code_of(script):
    """The files a script's code is in: the script and the drawing it calls, if any
    (``from reflectance.papers.draw.<figure> import run``)."""
    tree = ast.parse(script.read_text(), str(script))
    return [script, *(DRAWINGS / f"{node.module.rsplit('.', 1)[1]}.py" for node in tree.body
                      if isinstance(node, ast.ImportFrom)
                      and (node.module or "").startswith("reflectance.papers.draw."))]


def written_names(path):
    """The substitution names a script writes: the keys of the dicts it passes to
    ``write_caption_values``, directly or as the variable it fills (``values = {...}``,
    ``values.update({...})``). Keys must be literal strings, so a reader finds each name."""
    tree = ast.parse(path.read_text(), str(path))
    dicts = []
    for call in ast.walk(tree):
        if not (isinstance(call, ast.Call) and getattr(call.func, "id", None)
                == "write_caption_values"):
            continue
        values = call.args[1]
        if isinstance(values, ast.Dict):
            dicts.append(values)
            continue
        assert isinstance(values, ast.Name), f"{path}: the values are a dict or a variable"
        for node in ast.walk(tree):
            if isinstance(node, ast.Assign) and any(getattr(t, "id", None) == values.id
                                                    for t in node.targets):
                dicts.append(node.value)
            elif (isinstance(node, ast.Call) and isinstance(node.func, ast.Attribute)
                  and node.func.attr == "update" and getattr(node.func.value, "id", None)
                  == values.id):
                dicts += node.args
    names = set()
    while dicts:
        node = dicts.pop()
        assert isinstance(node, ast.Dict), f"{path}, line {node.lineno}: not a dict literal"
        for key, value in zip(node.keys, node.values):
            if key is None:  # **{...}
                dicts.append(value)
            else:
                assert isinstance(key, ast.Constant) and isinstance(key.value, str), (
                    f"{path}, line {key.lineno}: a caption value's name is a literal string")
                names.add(key.value)
    return names


def captions():
    return {path.name: path.read_text() for path in sorted(REPORT.glob("*.rst"))}


# --- the templates and the scripts ------------------------------------------------------------

def test_no_caption_types_a_computed_decimal():
    typed = {name: found for name, text in captions().items() if (found := typed_decimals(text))}
    assert typed == {}, "computed numbers come from the job's values file (reflectance.io.captions)"


def test_the_printed_decimals_are_printed_in_the_texts():
    if not PAPERS.is_dir():
        pytest.skip(f"the texts are not beside the project ({PAPERS})")
    texts = " ".join(p.read_text() for p in PAPERS.glob("*.txt"))
    printed = set(re.findall(r"(?<![\d.])\d+\.\d+", texts))
    printed |= {"0" + d for d in re.findall(r"(?<![\d.])\.\d+", texts)}  # Blinn prints ".4"
    assert set(PRINTED) - printed == set()
    used = {d for text in captions().values() for d in DECIMAL.findall(prose(text))}
    assert set(PRINTED) - used == set()  # none kept that no caption quotes


def test_every_substitution_a_caption_uses_is_written_by_its_script():
    """Each |name| of a caption is a key its script (or the drawing the script calls) writes to
    the job's values file, which the caption includes first; and each key a script or drawing
    writes is used by a caption naming it."""
    used_by_script = {}
    for name, text in captions().items():
        scripts = [code for script in scripts_named(text) for code in code_of(script)]
        for script in scripts:
            used_by_script.setdefault(script, set()).update(references(text))
        if not references(text):
            assert INCLUDE not in text, f"{name} includes values it does not use"
            continue
        assert text.startswith(INCLUDE + "\n\n"), f"{name}: the values file is included first"
        written = set().union(*(written_names(s) for s in scripts)) if scripts else set()
        assert references(text) - written == set(), (name, scripts)
    for script in sorted(SCRIPTS.glob("*.py")) + sorted(DRAWINGS.glob("*.py")):
        if "write_caption_values" in script.read_text():
            assert written_names(script) - used_by_script.get(script, set()) == set(), script


def test_the_checks_see_a_violation(tmp_path):
    """The checks above are not vacuous: a typed computed decimal, a name no script writes."""
    assert typed_decimals("peak {{ snakemake.params.m }} is 0.41 of §13.2 ``0.5``") == ["0.41"]
    assert typed_decimals("as printed, 0.9196; |a_peak|") == []
    script = tmp_path / "fig.py"
    script.write_text("values = {'a': '1'}\nvalues.update({'b': '2', **{'c': '3'}})\n"
                      "write_caption_values(out.values, values)\n")
    assert written_names(script) == {"a", "b", "c"}
    script.write_text("from reflectance.papers.draw.ct82_fig8 import run\nrun_job(snakemake, run)\n")
    assert written_names(script) == set() and code_of(script) == [script, DRAWINGS / "ct82_fig8.py"]
    assert references(f"{INCLUDE}\n\n|a| and |d|, ``|H|``, |x - y|") == {"a", "d"}
    script.write_text("values = {k: '1' for k in 'ab'}\nwrite_caption_values(out.values, values)\n")
    with pytest.raises(AssertionError, match="not a dict literal"):
        written_names(script)
    script.write_text("write_caption_values(out.values, {name: '1'})\n")
    with pytest.raises(AssertionError, match="a literal string"):
        written_names(script)


# --- end to end: three parameters changed, three figures rebuilt, their captions read -----------

CT82 = ("figures", "cook_torrance_1982")
#: (config key, new value): Fig. 6a's Beckmann m, Fig. 5c's averaging range, the roughness of
#: obsidian's vase in Fig. 7 (Table I's row)
EDITS = [
    (CT82 + ("fig6", "panels", "a", "m"), 0.25),
    (CT82 + ("fig5", "average_F0_range_nm"), [400, 700]),
    (CT82 + ("table1", "rows", 2, "m"), 0.3),
]
OUT = "results/cook_torrance_1982"
FIGURES = {"fig6": "ct82_fig6_published.rst", "fig5bc": "ct82_fig5bc.rst",
           "fig7": "ct82_fig7_published.rst"}


def after_build(runs, built, tmp_path_factory, items):
    """tests/conftest.py's ``early`` calls this when the session's build is done: the copy of the
    build with the three edits is made here and rebuilt (then reported) as a run of the pool."""
    if not any(item.originalname == "test_captions_state_the_rebuilt_tables" for item in items):
        return []
    from test_workflow import _edit_one_key

    cwd = tmp_path_factory.mktemp("captions") / "copy"
    shutil.copytree(built, cwd, symlinks=True, ignore=shutil.ignore_patterns("locks"))
    for key, value in EDITS:
        _edit_one_key(cwd, key, value)
    return [(60, "captions", _rebuild_and_report, (runs, cwd))]


def _rebuild_and_report(runs, cwd):
    """The three figures' jobs rerun in the edited copy, then Snakemake's report of them:
    ``(cwd, {figure: its caption as text})``."""
    from test_workflow import SNAKEMAKE

    proc = runs.run(SNAKEMAKE + ["--cores", "2"] + [f"{OUT}/{f}.values.rst" for f in FIGURES],
                    cwd=cwd)
    assert proc.returncode == 0, proc.stdout + proc.stderr
    proc = runs.run(SNAKEMAKE + ["--report", "report.html"] + [f"{OUT}/{f}.png" for f in FIGURES],
                    cwd=cwd)
    assert proc.returncode == 0, proc.stdout + proc.stderr
    page = (cwd / "report.html").read_text()
    start = page.index("var results = {") + len("var results = ")
    results, _ = json.JSONDecoder().raw_decode(page, start)
    return cwd, {figure: results[f"{OUT}/{figure}.png"]["caption"] for figure in FIGURES}


def _expected(cwd):
    """{figure: {substitution: the text its caption must show}}, from the rebuilt tables (and
    spectra/sources.csv), computed here, independently of the scripts."""
    import colour
    import numpy as np
    import pandas as pd

    def read(name):
        return pd.read_csv(cwd / OUT / name)

    fig6 = read("fig6.csv")
    a_printed, a_shown = fig6[fig6.panel == "a"].iloc[0], fig6[fig6.panel == "a"].iloc[-1]
    b = fig6[fig6.panel == "b"].iloc[0]
    printed = read("fig6_as_printed.csv").set_index("panel")
    irradiance = read("fig6_irradiance.csv").set_index("panel")
    config = yaml.safe_load((cwd / "config.yaml").read_text())
    shown_as = config["figures"]["cook_torrance_1982"]["fig6"]["published"]["display_variant"]
    variant = read(f"fig6_{shown_as['name']}.csv").drop_duplicates("panel").set_index("panel")
    d65 = colour.CCS_ILLUMINANTS["CIE 1931 2 Degree Standard Observer"]["D65"]
    _, F0_a, F0_b = colour.XYZ_to_Lab(b[["F0_X", "F0_Y", "F0_Z"]].to_numpy(float), d65)
    onset = read("fig5bc_approximation.csv").iloc[0]
    strip = read("fig5bc_strip.csv")
    rows = {m: strip[strip.method == m].sort_values("angle_deg") for m in ("exact", "approximation")}
    angles = rows["exact"].angle_deg.to_numpy(float)
    lab = {m: colour.XYZ_to_Lab(r[["X", "Y", "Z"]].to_numpy(float), d65) for m, r in rows.items()}
    dE = colour.delta_E(lab["exact"], lab["approximation"], method="CIE 2000")
    bound = config["figures"]["cook_torrance_1982"]["fig5"]["agreement_dE00"]
    agree, worst = angles[np.argmax(dE >= bound) - 1], int(np.argmax(dE))
    vases = read("fig7.csv").set_index("vase")
    span = vases.L99 - vases.L10
    munsell = pd.read_csv(cwd / "spectra" / "sources.csv").set_index("material").dataset
    lo, hi = config["figures"]["cook_torrance_1982"]["table1"]["average_F0_range_nm"]
    grid = np.arange(lo, hi + 1, config["wavelengths"]["step_nm"], dtype=float)
    carbon = pd.read_csv(cwd / "spectra" / "Carbon.csv")
    n, k = (np.interp(grid, carbon.wavelength_nm, carbon[c]) for c in ("n", "k"))
    carbon_F0 = ((n - 1) ** 2 + k**2) / ((n + 1) ** 2 + k**2)
    return {
        "fig6": {
            "ambient_headon": f"{100 * b.ambient_over_headon_diffuse_all_lights:.1f}",
            "ambient_highlight": f"{100 * b.ambient_over_direct_max:.2f}",
            "b_hue": f"{b.highlight_hue_deg:.1f}",
            "b_clipped": f"{100 * b.clipped:.1f}", "b_visible": f"{100 * b.visible:.0f}",
            "Cu_F0_hue": f"{np.degrees(np.arctan2(F0_b, F0_a)) % 360:.1f}",
            "a_F0": f"{a_printed.F0_Y:.3f}",
            "a_peak_ratio": f"{a_printed.specular_over_diffuse_peak:.2f}",
            "a_chroma": f"{a_printed.highlight_chroma_ratio:.2f}",
            "a_body_L": f"{a_printed.L50:.0f}", "a_body_C": f"{a_printed.body_chroma:.1f}",
            "a_body_hue": f"{a_printed.body_hue_deg:.1f}",
            "b_highlight_C": f"{b.body_chroma * b.highlight_chroma_ratio:.1f}",
            "variant_a_body_C": f"{variant.body_chroma.a:.1f}",
            "variant_b_highlight_C": f"{variant.body_chroma.b * variant.highlight_chroma_ratio.b:.1f}",
            "a_shown_chroma": f"{a_shown.highlight_chroma_ratio:.2f}",
            "intensity_ambient": f"{printed.ambient_over_headon_diffuse_weakest_light.a:.0f}",
            "irradiance_b_visible": f"{100 * irradiance.visible.b:.0f}",
            "irradiance_a_chroma": f"{irradiance.highlight_chroma_ratio.a:.2f}",
        },
        "fig5bc": {
            "F0_average": f"{onset.F0_average:.2f}", "n_average": f"{onset.n_average:.1f}",
            "dip": f"{-onset.dip:.2f}", "dip_deg": f"{onset.dip_deg:.1f}",
            "onset_deg": f"{onset.onset_deg:.2f}", "last_deg": f"{90 - onset.onset_deg:.2f}",
            "half_deg": f"{onset['t_0.5_deg']:.2f}",
            # "similar" read as CIEDE2000 below the config's bound: colour-science's own
            # XYZ -> Lab -> CIE 2000 on the strip's XYZ, not the job's dE column
            "agreement_dE00": f"{bound:g}", "agree_deg": f"{agree:g}",
            "worst_dE00": f"{dE[worst]:.1f}", "worst_deg": f"{angles[worst]:.1f}",
        },
        "fig7": {
            **{f"{v}_notation": munsell[v].removeprefix("Munsell ")
               for v in ("RustMunsell", "OliveDrab", "Rubber", "LunarDust", "Obsidian")},
            **{f"{v}_F0": f"{vases.F0_Y[v]:.2f}" for v in ("Obsidian", "Ag", "Carbon")},
            **{f"{v}_L": f"{vases.L50[v]:.0f}"
               for v in ("RustMunsell", "OliveDrab", "Rubber", "LunarDust", "Obsidian")},
            "Obsidian_visible": f"{100 * vases.visible.Obsidian:.0f}",
            "Obsidian_span": f"{span.Obsidian:.0f}", "LunarDust_span": f"{span.LunarDust:.1f}",
            "LunarDust_C": f"{vases.body_chroma.LunarDust:.0f}",
            # carbon: its median L* against the CIE 1976 lightness of its F0 (colour-science's),
            # and its F0 from the measured n, k by the textbook formula, over Table I's range
            "Carbon_L": f"{vases.L50.Carbon:.0f}",
            "Carbon_F0_L": f"{colour.colorimetry.lightness_CIE1976(100 * vases.F0_Y.Carbon):.0f}",
            "Carbon_F0_min": f"{carbon_F0.min():.2f}", "Carbon_F0_max": f"{carbon_F0.max():.2f}",
            "visible_lo": f"{lo:g}", "visible_hi": f"{hi:g}",
        },
    }


@pytest.mark.workflow
def test_captions_state_the_rebuilt_tables(built, after_build):
    """Fig. 6a's m, Fig. 5c's averaging range and obsidian's m in a copy of the build: each
    rebuilt caption (Snakemake's report of the three figures) shows, for every number it takes
    from its job, the value of the new tables, and the edits did change those numbers."""
    from reflectance.io.captions import read_caption_values

    cwd, rendered = after_build("captions")
    expected = _expected(cwd)
    old = _expected(built)
    for figure, template in FIGURES.items():
        names = references((REPORT / template).read_text())
        assert names == set(expected[figure]), figure  # every number the caption takes, checked
        written = read_caption_values(cwd / OUT / f"{figure}.values.rst")
        assert {name: written[name] for name in names} == expected[figure], figure
        caption = rendered[figure]
        assert "system-message" not in caption and "problematic" not in caption, caption
        text = " ".join(html.unescape(re.sub(r"<[^>]+>", " ", caption)).split())
        for name, value in expected[figure].items():
            assert f"|{name}|" not in text and value in text, (figure, name, value, text)
    # the edits reached the captions: the new m, and numbers that moved with each edit
    assert "m = 0.25" in " ".join(html.unescape(re.sub(r"<[^>]+>", " ", rendered["fig6"])).split())
    for figure, name in (("fig6", "a_peak_ratio"), ("fig5bc", "onset_deg"),
                         ("fig7", "Obsidian_span")):
        assert expected[figure][name] != old[figure][name], (figure, name)
