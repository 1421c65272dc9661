"""The article ("Specular highlight"): its figures that render nothing, one declaration each
(:class:`Figure`)."""

from __future__ import annotations

from reflectance.papers.figures.declaration import Figure

_OUT = "results/article"

DEFINITIONS = {figure.RULE: figure for figure in (
    Figure("article_distributions", _OUT, {"fig": "figures.article.distributions"},
           {"png": "distributions.png", "pdf": "distributions.pdf", "csv": "distributions.csv"}),
    Figure("article_phong_example", _OUT, {"fig": "figures.article.phong_example"},
           {"png": "phong_example.png", "pdf": "phong_example.pdf", "csv": "phong_example.csv",
            "values": "phong_example.values.rst"}),
)}
