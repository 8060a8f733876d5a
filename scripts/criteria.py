"""Issue 18's acceptance read from a `quadmesh mesh --report` JSON: the criteria a
mesh misses, for the scripts that print a row per input (parts-check, plate-sweep).

The shape and distance thresholds are the report's own "acceptance" (from
libquadmesh/pipeline/acceptance_criteria.h); the size band (at least 90% of the
quads within [0.5, 2] x the size, none above 3 x), the corners' quad counts and the
bound on interior singular vertices (max(24, 1% of the quads)) are the issue's.
"""

SIZE_BAND_GOAL = 0.9
MAX_SIZE_RATIO = 3.0


def corner_counts(report):
    """(corners wrong, corners in all) of the report's quality."""
    c = report["quality"]["corners"]
    return (c["convex_wrong"] + c["concave_wrong"] + c["other_wrong"],
            c["convex"] + c["concave"] + c["other"])


def missed_criteria(report):
    """The names of the criteria `report` misses (empty: it meets every one)."""
    q, a = report["quality"], report["acceptance"]
    wrong, _ = corner_counts(report)
    allowed = max(24, 0.01 * q["quads"])
    checks = [
        ("inverted", q["inverted"] + q["flipped"] == 0),
        ("SJ", q["min_scaled_jacobian"] >= a["min_scaled_jacobian"]),
        ("angle", q["angle_dev_mean"] <= a["max_mean_angle_deviation_deg"]),
        ("Hausdorff", q["hausdorff_rel"] <= a["max_hausdorff_relative"]),
        ("band", q["size_band_share"] >= SIZE_BAND_GOAL and q["size_ratio_max"] <= MAX_SIZE_RATIO),
        ("corners", wrong == 0),
        ("singular", q["irregular_interior"] <= allowed),
    ]
    return [name for name, ok in checks if not ok]
