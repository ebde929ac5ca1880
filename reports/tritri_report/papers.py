"""The papers' published figures: the only numbers in the report that do not come from the run.

Each is quoted with where it is printed, so a reader can check it against the paper.
"""

MOLLER97 = ("T. Möller, \"A Fast Triangle-Triangle Intersection Test\", journal of graphics tools "
            "2(2):25-30, 1997, section 3 \"Implementation & Performance\"")
TROPP06 = ("O. Tropp, A. Tal, I. Shimshoni, \"A fast triangle to triangle intersection test for "
           "collision detection\", Computer Animation and Virtual Worlds 17(5):527-535, 2006, abstract "
           "and results (as summarised in shared/notes/algorithms.md; the paper is not in shared/papers)")
SABHARWAL15 = ("C. L. Sabharwal, J. L. Leopold, \"A Triangle-Triangle Intersection Algorithm\", 2015, "
               "section 4 (Experimental results), Table 1")
YUHE13 = ("Yu Haiyan (于海燕), He Yuanjun (何援军), \"空间两三角形的相交问题\" (the intersection of two spatial triangles), "
          "2013, section 7.1 (test set) and 7.2, Table 1")
HELD97 = ("M. Held, \"ERIT - A Collection of Efficient and Reliable Intersection Tests\", journal of "
          "graphics tools 2(4), 1997 (not available; reconstructed from Möller 1997 and Tropp 2006)")
GUIGUE03 = ("P. Guigue, O. Devillers, \"Fast and Robust Triangle-Triangle Overlap Test Using "
            "Orientation Predicates\", journal of graphics tools 8(1), 2003 (not in shared/papers)")

# Möller 1997, "Performance": brute force "took between 1.3 and 1.6 times longer to execute";
# "approximately 7 percent faster [than ERIT] on an SGI Impact"; on an SGI O2 "the break even
# point was around 45 percent", Möller's test faster at lower collision ratios.
MOLLER_BRUTE_RANGE = (1.3, 1.6)
MOLLER_VS_ERIT_FASTER = 0.07
MOLLER_ERIT_BREAK_EVEN = 0.45

# Tropp et al. 2006: about 20% fewer arithmetic operations than the best earlier test and
# 18.9% faster on average (Pentium 4).
TROPP_FEWER_OPS = 0.20
TROPP_FASTER = 0.189

# Sabharwal & Leopold 2015, Table 1 (seconds per pair, MacPython 3.3.3, 2.2 GHz Core i7;
# 100 runs over 3 disjoint, 6 point, 4 segment and 9 area pairs).
SABHARWAL_TABLE1 = {"disjoint": 0.000073, "point": 0.000531, "segment": 0.001483, "area": 0.001962}
SABHARWAL_OVERALL = 0.001353
SABHARWAL_SAMPLES = {"disjoint": 3, "point": 6, "segment": 4, "area": 9}

# Yu & He 2013, Table 1: 40 pairs x 10^6 repetitions, seconds. "单变换" transform alone,
# "单求交" intersection in the frame alone, "变换+求交" both.
YUHE_TABLE1 = [
    {"machine": "IBM Thinkpad T60p (laptop), Windows XP", "transform": 7.0, "frame": 38.0, "both": 47.0},
    {"machine": "Pentium Dual-Core E6500 2.93 GHz, Windows XP", "transform": 5.0, "frame": 28.0, "both": 31.0},
]
YUHE_PAIRS = 40e6
YUHE_SINGULAR = 23  # section 7.1: 23 singular positions of B, and 30 others, all handled
YUHE_OTHER = 30
