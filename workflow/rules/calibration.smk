rule calibrate_mean:
    """Figure 2a on the mean-behaviour model: axial stretch, then 0-200 mmHg, beside the exact thick wall."""
    input:
        code=code_of("calibrate_mean"),
    output:
        states=report(
            "results/calibration/mean_pressure_diameter.csv",
            caption="../report/mean_pressure_diameter.rst",
            category="1 Calibration",
            labels={"result": "Table: mean model, one state per pressure"},
        ),
        exact="results/calibration/mean_exact_curve.csv",
        transmural="results/calibration/transmural_mean.csv",
        provenance="results/provenance/calibrate_mean.json",
    log:
        "logs/calibrate_mean.log",
    benchmark:
        "results/benchmarks/calibrate_mean.tsv"
    threads: 1
    params:
        mean=config["mean"],
        numerics=config["numerics"],
        calibration=config["calibration"],
    script:
        "../scripts/calibrate_mean.py"
