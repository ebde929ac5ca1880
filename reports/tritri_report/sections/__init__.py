"""The report's sections, in order: the one list to change to add, drop or move one.

A section is a module with
  TITLE      its heading (or a function of the Run giving it);
  LEVEL      2 (a part, the default) or 3 (a subsection of the part before it); 1 for the title;
  NUMBERED   False for a heading without a number (default True: parts are numbered in order,
             a numbered subsection continues its part's numbering);
  render(run, part)  reads the Run (report.Run: the JSON, the published files) and adds its
             Markdown and figures to the Part (report.Part: add, heading, figure).
The report writes each heading, then calls render.
"""

from . import (asymmetry, authors, baseline, compiler, correctness, exact_test, float_double, float_speed, gallery,
               header, hunt, moller97, papers, provenance, sabharwal15, scenes, scorecard, shen03, speed_error,
               stability, summary, time_ratio, tropp06, unquoted, web_peers, yuhe13)

SECTIONS = [
    header,
    summary,
    correctness,
    asymmetry,
    scorecard,
    baseline,
    hunt,
    speed_error,
    time_ratio,
    exact_test,
    stability,
    float_double,
    compiler,
    papers,
    moller97,
    tropp06,
    shen03,
    sabharwal15,
    yuhe13,
    unquoted,
    float_speed,
    authors,
    scenes,
    web_peers,
    gallery,
    provenance,
]
