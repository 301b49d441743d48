# The package's physics sources as one file: the code input of every simulation (common.smk: SPHGAG).


rule package_digest:
    """The sha256 of every module the simulations depend on, one per line: their code input (SPHGAG)."""
    input:
        SPHGAG_MODULES,
    output:
        SPHGAG,
    log:
        "logs/package_digest.log",
    benchmark:
        "results/benchmarks/package_digest.tsv"
    localrule: True
    script:
        "../scripts/package_digest.py"
