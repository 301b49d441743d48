# The code input of the rules that run a script: the package modules its job imports as one file per script
# (common.smk: CODE, code_of).


rule package_digest:
    """The sha256 of every module that the job of workflow/scripts/{script}.py imports, one per line: the code input
    of the rules that run the script (code_of)."""
    input:
        lambda wildcards: CODE[wildcards.script],
    output:
        "results/code/{script}.sha256",
    log:
        "logs/package_digest/{script}.log",
    benchmark:
        "results/benchmarks/package_digest_{script}.tsv"
    wildcard_constraints:
        script=one_of(script for script, modules in CODE.items() if modules),
    localrule: True
    script:
        "../scripts/package_digest.py"
