"""One definition per figure (reflectance.papers.figures): what the config check validates is
what the job writes; a one-key edit of config.yaml reruns exactly the figures whose definitions
declare that key; adding a light to Blinn's Fig. 7 is an edit of config.yaml alone."""

from __future__ import annotations

import copy
import re
import shutil
from pathlib import Path

import pytest
import yaml

from reflectance.config import ConfigError, check_config
from reflectance.papers.figures import (ANALYTIC, FIGURES, READERS, config_value,
                                        declared_key_problems, figure, figure_scenes, params_of,
                                        rule_keys, select)
from test_workflow import SNAKEMAKE, _planned_jobs

ROOT = Path(__file__).resolve().parents[1]
CONFIG = yaml.safe_load((ROOT / "config.yaml").read_text())


def _scene_files(outputs):
    return sorted(p for value in outputs.values()
                  for p in ([value] if isinstance(value, str) else value)
                  if p.endswith(".scene.yaml"))


#: the rules files of the figures that render nothing, each with its text's module
TEXTS = {"cook_torrance_1982.smk": "cook_torrance_1982", "blinn_1977.smk": "blinn_1977",
         "lecture.smk": "lecture", "article.smk": "article"}


def test_every_figure_module_is_listed_once():
    """FIGURES and figure()'s imports name the same modules: every module of the package but
    its shared declaration and the texts' modules, each under its rule's name."""
    import reflectance.papers.figures as package

    folder = Path(package.__file__).parent
    assert set(FIGURES) == ({p.stem for p in folder.glob("*.py")}
                            - {"__init__", "declaration", *TEXTS.values()})
    assert all(figure(name).RULE == name for name in FIGURES + ANALYTIC)


def test_every_analytic_rule_takes_its_definition():
    """ANALYTIC is exactly the rules of the four texts' rules files, and each of those rules
    takes its params and outputs from its own definition (``X = figure_def("rule")``)."""
    import importlib

    rules = []
    for smk, text in TEXTS.items():
        source = (ROOT / "workflow/rules" / smk).read_text()
        names = dict(re.findall(r'(?m)^(\w+) = figure_def\("(\w+)"\)$', source))
        for block in re.split(r"(?m)^(?=rule )", source)[1:]:
            rule = re.match(r"rule (\w+):", block).group(1)
            rules.append(rule)
            assert rule in importlib.import_module(f"reflectance.papers.figures.{text}")\
                .DEFINITIONS, (smk, rule)
            var = {r: v for v, r in names.items()}[rule]
            params = re.search(r"(?ms)^    params:\n(.*?)^    \w", block).group(1)
            assert f"**{var}.params," in params or f'{var}.params["' in params, rule
            outputs = re.search(r"(?ms)^    output:\n(.*?)^    \w", block).group(1)
            assert "results/" not in outputs and f"{var}.outputs[" in outputs, rule
    assert sorted(rules) == sorted(ANALYTIC)


def test_the_config_check_names_a_declared_key_that_is_absent():
    """A key a figure declares (so reads) but config.yaml lacks: one line naming the key and
    the figure, from the config check, before any rule takes its params."""
    config = copy.deepcopy(CONFIG)
    del config["figures"]["blinn_1977"]["fig1_4"]["construction_case"]
    assert declared_key_problems(config) == [
        "config.yaml has no figures.blinn_1977.fig1_4.construction_case (needed by figure "
        "blinn77_fig2_4, reflectance.papers.figures)"]
    with pytest.raises(ConfigError, match="fig1_4.construction_case .needed by figure "
                                          "blinn77_fig2_4"):
        check_config(config, check_spectra=False, check_scenes=False)


@pytest.mark.parametrize("name", FIGURES)
def test_each_scene_file_output_is_one_scene(name):
    """Every .scene.yaml among a figure's outputs is written by exactly one of its scenes."""
    module = figure(name)
    params = params_of(module, CONFIG)
    written = [item.file for item in module.scenes(params, "spectra") if item.written]
    assert sorted(written) == _scene_files(module.outputs(params))


def test_the_config_check_sees_every_figures_scenes():
    labels = [label for _, label, _ in figure_scenes(CONFIG)]
    assert len(labels) == len(set(labels))  # each render named once
    assert sum(len(figure(name).scenes(params_of(figure(name), CONFIG), "spectra"))
               for name in FIGURES) == len(labels)
    assert {"fig6a", "fig6a_as_printed", "fig7/Cu", "fig8", "fig8a", "spheres",
            "fig7a_torrance_sparrow_edge"} <= set(labels)


def test_a_figure_is_handed_only_its_declared_keys():
    """C&T Fig. 7's params hold the parts of Fig. 6 its vases are rendered with, not Fig. 6a's
    panel: a key a figure's code reads without declaring it is a KeyError at the config check."""
    params = params_of(figure("ct82_fig7"), CONFIG)
    assert set(params["fig6"]["panels"]) == {"b"}
    assert "published" not in params["fig6"]
    broken = {**params, "fig6": {k: v for k, v in params["fig6"].items() if k != "camera"}}
    with pytest.raises(KeyError, match="camera"):
        figure("ct82_fig7").scenes(broken, "spectra")


def test_the_close_ups_light_must_be_a_light():
    params = params_of(figure("blinn77_fig7"), CONFIG)
    params["fig"]["rim_closeup"]["light"] = "back"
    with pytest.raises(ValueError, match=r"fig7\.rim_closeup\.light: 'back' is not a light; "
                                         r"known: tangential, edge, front"):
        figure("blinn77_fig7").scenes(params)


def test_select_names_a_missing_key():
    with pytest.raises(KeyError, match="figures.cook_torrance_1982.fig6.nothing"):
        select({"x": ("figures.cook_torrance_1982.fig6.nothing",)}, CONFIG)


def test_scenes_the_check_validates_are_the_scenes_the_jobs_write(built, monkeypatch):
    """In the session's build, every .scene.yaml a rendered figure wrote is the validated form of
    the scene its definition gives (what reflectance.config checked at parse time)."""
    from reflectance.render.scene import scene_from_dict

    monkeypatch.chdir(built)  # the scenes name spectra/ relative to the project
    config = yaml.safe_load((built / "config.yaml").read_text())
    compared = 0
    for name in FIGURES:
        module = figure(name)
        for item in module.scenes(params_of(module, config), "spectra"):
            if not item.written:
                continue
            expected = scene_from_dict(copy.deepcopy(item.document), source=item.name).document
            assert yaml.safe_load((built / item.file).read_text()) == expected, item.file
            compared += 1
    assert compared >= 40  # C&T Fig. 7 alone writes 39 (13 vases x 3 variants)


# --- exact rebuilds -------------------------------------------------------------------------------

#: the rules that read a figure's files (not its keys): they run again whenever it does
READ_BY = {"ct82_fig6": {"audit_gamut_mapping", "readme_strip"},
           "ct82_fig7": {"audit_gamut_mapping", "readme_strip"},
           "ct82_fig8": {"audit_gamut_mapping"}, "blinn77_fig7": {"audit_gamut_mapping"},
           "blinn77_fig8": {"audit_gamut_mapping"}, "article_spheres": {"audit_gamut_mapping"},
           "blinn77_fig7_sweep": set(), "audit_rgb_rendering": set(),
           # of the figures that render nothing, README's strip reads Fig. 5c's colours
           **{rule: set() for rule in ANALYTIC}, "ct82_fig5bc": {"readme_strip"},
           # Fig. 4's caption states the copper datasets' comparison (its job reads the table)
           "ct82_fig4_copper": {"ct82_fig4"},
           "blinn77_cost_counts": {"blinn77_cost_timing"}}
#: provenance hashes every output: it runs again after any job
AGGREGATING = {"provenance"}

#: one-key edits of config.yaml: (dotted key, new value)
EDITS = [
    ("figures.cook_torrance_1982.fig6.panels.a.m", 0.25),
    ("figures.cook_torrance_1982.fig6.camera.fov_deg", 26),
    ("figures.cook_torrance_1982.fig6.published.exposure.highlight_knee", 0.7),
    ("figures.cook_torrance_1982.fig7.vase_exposure.Obsidian", 2.5),
    ("figures.cook_torrance_1982.fig8.light.intensity", 0.9),
    ("figures.blinn_1977.fig7.panels.b.c3", 0.4),
    ("figures.blinn_1977.fig7.lights.front.angle_deg", 20),
    ("figures.blinn_1977.fig7.rim_closeup.fov_deg", 0.3),
    ("figures.blinn_1977.fig7_sweep.n_frames", 29),
    ("figures.blinn_1977.fig8.p_s", 0.8),
    ("figures.article.spheres.m", 0.2),
]

#: one-key edits of the figures that render nothing, across the four texts: dry-run one after
#: another in one copy of the build (each edit undone before the next)
ANALYTIC_EDITS = [
    ("figures.cook_torrance_1982.fig3.alpha_step_deg", 0.5),
    ("figures.cook_torrance_1982.fig4_copper.red_nm", [610, 700]),  # the comparison, Fig. 4's caption
    ("figures.cook_torrance_1982.fig4.axis_nm", [400, 700]),  # Fig. 4 alone, not the comparison
    ("figures.cook_torrance_1982.fig5.surface_angle_step_deg", 2),  # Fig. 5a only
    ("figures.cook_torrance_1982.fig5.average_F0_range_nm", [400, 700]),  # Fig. 5c only
    ("figures.cook_torrance_1982.table1.average_F0_range_nm", [400, 700]),
    ("figures.errata.theta_deg", 70),
    ("figures.blinn_1977.fig1_4.construction_case", "c"),  # Figs. 2-4, not Fig. 1
    ("figures.blinn_1977.fig1_4.n_rays", 50000),  # Figs. 1 and 2-4
    ("figures.blinn_1977.fig5_6.incidence_deg.fig5", 35),
    ("figures.blinn_1977.distributions.alpha_step_deg", 0.1),
    ("figures.blinn_1977.cost.panel", "a"),  # the counts and the timing
    ("figures.blinn_1977.cost.n_samples", 500000),  # the timing only
    ("figures.lecture.brdf_lobes.polar_step_deg", 0.5),  # the 2-D lobes, not the 3-D
    ("figures.lecture.brdf_lobes.hemisphere_samples", [91, 181]),  # the 3-D lobes only
    ("figures.lecture.shadowing_masking.view_deg", 70),
    ("figures.lecture.distributions.m", [0.3, 0.6]),
    ("figures.article.distributions.models.phong.n", 30),
    ("figures.article.phong_example.n", 4),
]


def _overlaps(key, declared):
    return any(key == d or key.startswith(d + ".") or d.startswith(key + ".") for d in declared)


def expected_plan(key, config):
    """The jobs a dry run must plan after editing ``key``: every rule whose definition declares
    the key (or a key above or below it), what reads their files, and the aggregating rules."""
    readers = {rule for rule in (*FIGURES, *ANALYTIC, *READERS)
               if _overlaps(key, rule_keys(rule, config))}
    return readers | {r for rule in readers for r in READ_BY[rule]} | AGGREGATING


def _edit(config, key, value):
    parts = key.split(".")
    node = config_value(config, ".".join(parts[:-1]))
    assert parts[-1] in node and node[parts[-1]] != value, key
    node[parts[-1]] = value


def test_every_edit_changes_a_key_some_figure_reads():
    for key, value in EDITS + ANALYTIC_EDITS:
        _edit(copy.deepcopy(CONFIG), key, value)  # the key exists and the value is new
        assert expected_plan(key, CONFIG) - AGGREGATING, key


#: a light added to Blinn's Fig. 7
NEW_LIGHT = {"side": {"angle_deg": 95, "azimuth_deg": 0}}


def after_build(runs, built, tmp_path_factory, items):
    """tests/conftest.py's ``early`` calls this when the session's build is done: a dry run in
    a copy of the build per edit of EDITS, and a run of Blinn Fig. 7 with a third light."""
    names = {item.originalname for item in items}
    starts = []
    if "test_a_one_key_edit_plans_exactly_what_the_definitions_say" in names:
        selected = {item.callspec.params["edit"] for item in items
                    if item.originalname == "test_a_one_key_edit_plans_exactly_what_the_"
                                            "definitions_say"}
        for i in sorted(selected):
            cwd = _copy(built, tmp_path_factory)
            config = yaml.safe_load((cwd / "config.yaml").read_text())
            _edit(config, *EDITS[i])
            (cwd / "config.yaml").write_text(yaml.safe_dump(config, sort_keys=False))
            starts.append((5, ("figure edit", i), _dry_run, (runs, cwd)))
    if "test_an_analytic_one_key_edit_plans_exactly_what_the_definitions_say" in names:
        cwd = _copy(built, tmp_path_factory)
        starts.append((5 * len(ANALYTIC_EDITS), "analytic edits", _dry_runs, (runs, cwd)))
    if "test_a_light_added_in_config_is_rendered" in names:
        cwd = _copy(built, tmp_path_factory)
        config = yaml.safe_load((cwd / "config.yaml").read_text())
        config["figures"]["blinn_1977"]["fig7"]["lights"].update(NEW_LIGHT)
        (cwd / "config.yaml").write_text(yaml.safe_dump(config, sort_keys=False))
        starts.append((40, "new light", _new_light, (runs, cwd)))
    return starts


def _copy(built, tmp_path_factory):
    cwd = tmp_path_factory.mktemp("figure-edit") / "copy"
    shutil.copytree(built, cwd, symlinks=True, ignore=shutil.ignore_patterns("locks"))
    return cwd


def _dry_run(runs, cwd):
    return runs.run(SNAKEMAKE + ["-n", "--cores", "2"], cwd=cwd)


def _dry_runs(runs, cwd):
    """A dry run per edit of ANALYTIC_EDITS, one after another in one copy of the build."""
    original = (cwd / "config.yaml").read_text()
    procs = []
    for key, value in ANALYTIC_EDITS:
        config = yaml.safe_load(original)
        _edit(config, key, value)
        (cwd / "config.yaml").write_text(yaml.safe_dump(config, sort_keys=False))
        procs.append(_dry_run(runs, cwd))
    (cwd / "config.yaml").write_text(original)
    return procs


def _new_light(runs, cwd):
    # README's build command, every target: Snakemake checks a job's params only where every output
    # has its record, so a run asking for the figure's old files alone would not see the light
    return cwd, runs.run(SNAKEMAKE + ["--cores", "2"], cwd=cwd)


@pytest.mark.parametrize("edit", range(len(EDITS)), ids=[key for key, _ in EDITS])
def test_a_one_key_edit_plans_exactly_what_the_definitions_say(after_build, edit):
    """The parameters guide (workflow/docs/guides/parameters.rst): after editing one
    key, Snakemake reruns exactly the outputs that depend on it."""
    proc = after_build(("figure edit", edit))
    text = proc.stdout + proc.stderr
    assert proc.returncode == 0, text
    assert set(_planned_jobs(text)) == expected_plan(EDITS[edit][0], CONFIG) | {"all"}, text


@pytest.mark.parametrize("edit", range(len(ANALYTIC_EDITS)),
                         ids=[key for key, _ in ANALYTIC_EDITS])
def test_an_analytic_one_key_edit_plans_exactly_what_the_definitions_say(after_build, edit):
    """The same for the figures that render nothing, in all four texts: a key two figures
    share reruns both, a key of one of them that one alone."""
    proc = after_build("analytic edits")[edit]
    text = proc.stdout + proc.stderr
    assert proc.returncode == 0, text
    assert set(_planned_jobs(text)) == expected_plan(ANALYTIC_EDITS[edit][0], CONFIG) | {"all"}, \
        text


def test_a_light_added_in_config_is_rendered(after_build):
    """Blinn Fig. 7 with a third light, an edit of config.yaml alone: the config check passes,
    the job renders one more row (its files, its table rows) and nothing else is needed."""
    cwd, proc = after_build("new light")
    text = proc.stdout + proc.stderr
    assert proc.returncode == 0, text
    # the figure, the audit that reads its EXRs (the new ones too) and the manifest: not the
    # sweep or Fig. 8, which take Fig. 7's object and camera but not its lights
    assert set(_planned_jobs(text)) == {"blinn77_fig7", "audit_gamut_mapping", "provenance",
                                        "all"}, text
    import pandas as pd

    table = pd.read_csv(cwd / "results/blinn_1977/fig7.csv")
    # (and the default figure's grazing view: its edge light and the front light on the bar)
    assert set(table.light) == {"edge", "front", "tangential", "side", "grazing_edge",
                                "grazing_front"}
    assert len(table[table.light == "side"]) == 4  # 2 panels x 2 readings of Phong's p_s
    for reading in ("as_printed", "matched"):  # each light but the front one: a figure of its own
        assert (cwd / "results/blinn_1977" / f"fig7_{reading}_side.png").is_file(), reading
    for stem in ("fig7a_torrance_sparrow_side", "fig7b_phong_side_matched"):
        for ext in ("exr", "png", "scene.yaml"):
            assert (cwd / "results/blinn_1977" / f"{stem}.{ext}").is_file(), stem
    images = pd.read_csv(cwd / "results/audits/gamut_mapping_images.csv")
    assert images.to_string().count("_side") >= 6  # the audit reads the new renders
