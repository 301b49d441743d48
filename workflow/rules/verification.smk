from sphgag.studies import crack
from sphgag.studies.annulus import AnnulusVerification
from sphgag.studies.inclusion import Materials, PoolVerification
from sphgag.studies.swollen_pool import CircularPoolVerification

VP = config["verification"]["pool"]
ASPECT_RATIOS = text(VP["aspect_ratios"])
# the matrix of the verification is the elastin law of the bi-layered model (unweighted); GAG as in the study
POOL_MATRIX = {
    "shear_modulus_kPa": config["bilayer"]["elastin_shear_modulus_kPa"],
    "lame_lambda_kPa": config["bilayer"]["lame_lambda_kPa"],
    "hourglass_modulus_kPa": config["bilayer"]["hourglass_modulus_kPa"],
}
# the GAG of the large-strain verifications: the study's, with its volumetric term (gag.volumetric)
POOL_GAG = Materials.gag_settings(config["gag"], bulk=True)


wildcard_constraints:
    ratio=one_of(ASPECT_RATIOS),


rule verify_pool_ratio:
    """Pressurised elliptical inclusion (a/b = {ratio}) at every resolution, against Inglis (and Lame)."""
    input:
        code=code_of("verify_pool"),
    output:
        table=JOBS.verify_pool_ratio.flat_output("verification/runs", "elliptic_pool", ".csv"),
        profiles=JOBS.verify_pool_ratio.flat_output("verification/runs", "elliptic_pool_profiles", ".csv"),
        provenance=JOBS.verify_pool_ratio.provenance,
    log:
        JOBS.verify_pool_ratio.log,
    benchmark:
        JOBS.verify_pool_ratio.benchmark
    threads: 1
    resources:
        mem_mb=2000,
    params:
        pool=PoolVerification.job_settings(VP),
        matrix=POOL_MATRIX,
        gag=Materials.gag_settings(config["gag"]),
        numerics=config["numerics"],
    script:
        "../scripts/verify_pool.py"


rule verify_pool:
    """The pool verification of every aspect ratio in one table."""
    input:
        expand(rules.verify_pool_ratio.output.table, ratio=ASPECT_RATIOS),
    output:
        report(
            "results/verification/elliptic_pool.csv",
            caption="../report/elliptic_pool.rst",
            category="4 Verification",
            labels={"result": "Table: the pool verification"},
        ),
    log:
        "logs/verify_pool.log",
    benchmark:
        "results/benchmarks/verify_pool.tsv"
    script:
        "../scripts/concat_tables.py"


rule verify_pool_profiles:
    """The stress profiles of the pool verification (axis and, for a circle, rings) in one table."""
    input:
        expand(rules.verify_pool_ratio.output.profiles, ratio=ASPECT_RATIOS),
    output:
        "results/verification/elliptic_pool_profiles.csv",
    log:
        "logs/verify_pool_profiles.log",
    benchmark:
        "results/benchmarks/verify_pool_profiles.tsv"
    script:
        "../scripts/concat_tables.py"


rule verification_pool_figure:
    """SPH around a swelling inclusion against Inglis and Lame; errors against resolution with the observed order."""
    input:
        code=code_of("verification_pool_figure"),
        table=rules.verify_pool.output[0],
        profiles=rules.verify_pool_profiles.output[0],
    output:
        pdf="figures/verification_pool.pdf",
        png=report(
            "figures/verification_pool.png",
            caption="../report/verification_pool.rst",
            category="4 Verification",
            labels={"result": "Figure: a swelling inclusion against Inglis and Lame"},
        ),
    log:
        "logs/verification_pool_figure.log",
    benchmark:
        "results/benchmarks/verification_pool_figure.tsv"
    threads: 1
    script:
        "../scripts/verification_pool_figure.py"


VC = config["verification"]["crack"]
CRACK_LENGTHS = text(VC["half_lengths_um"])


rule verify_crack_length:
    """Pressurised crack of half-length {length} um at every spacing: the fracture-energy damage law against Sneddon,
    Griffith and G_c."""
    input:
        code=code_of("verify_crack"),
    output:
        table=JOBS.verify_crack_length.flat_output("verification/runs", "pressurised_crack", ".csv"),
        provenance=JOBS.verify_crack_length.provenance,
    log:
        JOBS.verify_crack_length.log,
    benchmark:
        JOBS.verify_crack_length.benchmark
    wildcard_constraints:
        length=one_of(CRACK_LENGTHS),
    threads: 1
    resources:
        runtime=45,
        mem_mb=6500,
    params:
        crack=VC,
        matrix=POOL_MATRIX,
        gag=crack.gag_settings(config["gag"]),
        numerics=config["numerics"],
    script:
        "../scripts/verify_crack.py"


rule verify_crack:
    """The crack verification of every half-length in one table."""
    input:
        expand(rules.verify_crack_length.output.table, length=CRACK_LENGTHS),
    output:
        report(
            "results/verification/pressurised_crack.csv",
            caption="../report/pressurised_crack.rst",
            category="4 Verification",
            labels={"result": "Table: the pressurised crack"},
        ),
    log:
        "logs/verify_crack.log",
    benchmark:
        "results/benchmarks/verify_crack.tsv"
    script:
        "../scripts/concat_tables.py"


rule verification_crack_figure:
    """The fracture-energy damage law on a pressurised crack: SPH against Sneddon and Griffith, and the errors against
    resolution."""
    input:
        code=code_of("verification_crack_figure"),
        table=rules.verify_crack.output[0],
    output:
        pdf="figures/verification_crack.pdf",
        png=report(
            "figures/verification_crack.png",
            caption="../report/verification_crack.rst",
            category="4 Verification",
            labels={"result": "Figure: the fracture-energy law against Sneddon and Griffith"},
        ),
    log:
        "logs/verification_crack_figure.log",
    benchmark:
        "results/benchmarks/verification_crack_figure.tsv"
    threads: 1
    script:
        "../scripts/verification_crack_figure.py"


VCP = config["verification"]["circular_pool"]


rule verify_circular_pool_model:
    """A circular pool swollen to large strain ({model}: the paper's GAG particles, or the pool as a pressurised
    cavity) at every spacing, against the exact radially symmetric solution of the same laws."""
    input:
        code=code_of("verify_circular_pool"),
    output:
        table=JOBS.verify_circular_pool_model.flat_output("verification/runs", "circular_pool", ".csv"),
        provenance=JOBS.verify_circular_pool_model.provenance,
    log:
        JOBS.verify_circular_pool_model.log,
    benchmark:
        JOBS.verify_circular_pool_model.benchmark
    wildcard_constraints:
        model=one_of(VCP["pool_models"]),
    threads: 1
    resources:
        runtime=30,
        mem_mb=2000,
    params:
        pool=CircularPoolVerification.job_settings(VCP),
        matrix=POOL_MATRIX,
        gag=POOL_GAG,
        numerics=config["numerics"],
    script:
        "../scripts/verify_circular_pool.py"


rule verify_circular_pool:
    """The large-strain verification of every pool model in one table."""
    input:
        expand(rules.verify_circular_pool_model.output.table, model=VCP["pool_models"]),
    output:
        report(
            "results/verification/circular_pool.csv",
            caption="../report/circular_pool.rst",
            category="4 Verification",
            labels={"result": "Table: a circular pool at large strain"},
        ),
    log:
        "logs/verify_circular_pool.log",
    benchmark:
        "results/benchmarks/verify_circular_pool.tsv"
    script:
        "../scripts/concat_tables.py"


rule verification_circular_pool_figure:
    """The circular pool at large strain: errors of the pool's volume and of its lining's radius against dx."""
    input:
        code=code_of("verification_circular_pool_figure"),
        table=rules.verify_circular_pool.output[0],
    output:
        pdf="figures/verification_circular_pool.pdf",
        png=report(
            "figures/verification_circular_pool.png",
            caption="../report/verification_circular_pool.rst",
            category="4 Verification",
            labels={"result": "Figure: a circular pool at large strain against its exact solution"},
        ),
    log:
        "logs/verification_circular_pool_figure.log",
    benchmark:
        "results/benchmarks/verification_circular_pool_figure.tsv"
    threads: 1
    script:
        "../scripts/verification_circular_pool_figure.py"


VAN = config["verification"]["annulus"]


rule verify_annulus_model:
    """The prescribed law's limit of existence ({model}: an empty hole, or the paper's GAG particles): a pressurised
    annulus at every spacing below, and above, the largest pressure its exact solution holds."""
    input:
        code=code_of("verify_annulus"),
    output:
        table=JOBS.verify_annulus_model.flat_output("verification/runs", "annulus", ".csv"),
        provenance=JOBS.verify_annulus_model.provenance,
    log:
        JOBS.verify_annulus_model.log,
    benchmark:
        JOBS.verify_annulus_model.benchmark
    wildcard_constraints:
        model=one_of(VAN["pool_models"]),
    threads: 1
    resources:
        runtime=60,
        mem_mb=2000,
    params:
        annulus=AnnulusVerification.job_settings(VAN),
        matrix=POOL_MATRIX,
        gag=POOL_GAG,
        numerics=config["numerics"],
    script:
        "../scripts/verify_annulus.py"


rule verify_annulus:
    """The annulus verification of every pool model in one table, and the observed order of each measure."""
    input:
        code=code_of("verify_annulus_orders"),
        tables=expand(rules.verify_annulus_model.output.table, model=VAN["pool_models"]),
    output:
        table=report(
            "results/verification/annulus.csv",
            caption="../report/annulus.rst",
            category="4 Verification",
            labels={"result": "Table: the pressurised annulus and its limit of existence"},
        ),
        orders="results/verification/annulus_orders.csv",
        exact="results/verification/annulus_exact.csv",
    log:
        "logs/verify_annulus.log",
    benchmark:
        "results/benchmarks/verify_annulus.tsv"
    threads: 1
    params:
        radius=VAN["radius_um"],
        matrix=POOL_MATRIX,
        gag=POOL_GAG,
    script:
        "../scripts/verify_annulus_orders.py"


rule verification_annulus_figure:
    """The pressurised annulus: pressure against volume ratio beside the exact curve and its limit, and the errors
    against dx."""
    input:
        code=code_of("verification_annulus_figure"),
        table=rules.verify_annulus.output.table,
        orders=rules.verify_annulus.output.orders,
        exact=rules.verify_annulus.output.exact,
    output:
        pdf="figures/verification_annulus.pdf",
        png=report(
            "figures/verification_annulus.png",
            caption="../report/verification_annulus.rst",
            category="4 Verification",
            labels={"result": "Figure: the pressurised annulus against its exact solution and its limit"},
        ),
    log:
        "logs/verification_annulus_figure.log",
    benchmark:
        "results/benchmarks/verification_annulus_figure.tsv"
    threads: 1
    script:
        "../scripts/verification_annulus_figure.py"


VPR = config["verification"]["profiles"]
PROFILE_SECTIONS = sorted({"mean" if w == "mean" else "bilayer" for w in VPR["walls"]})


rule verify_profiles_wall:
    """The {section} wall at refinement level {level} under the {load} lumen load: every ring's radial and hoop stress,
    read by each stress recovery, against the exact thick wall."""
    input:
        code=code_of("verify_profiles_wall"),
    output:
        table=JOBS.verify_profiles_wall.flat_output("verification/runs", "profiles", ".csv"),
        provenance=JOBS.verify_profiles_wall.provenance,
    log:
        JOBS.verify_profiles_wall.log,
    benchmark:
        JOBS.verify_profiles_wall.benchmark
    wildcard_constraints:
        section="mean|bilayer",
        level=r"\d+",
        load=one_of(VPR["lumen_loads"]),
    threads: 1
    resources:
        runtime=120,
        mem_mb=6000,
    params:
        # what the job's path reads: the axial stretch's steps (mean wall); the homeostasis without its reference
        # pressure and the activation (bi-layered wall)
        wall=lambda w: config[w.section],
        walls=lambda w: [v for v in VPR["walls"] if v != "mean"] if w.section == "bilayer" else [],
        pressures=VPR["pressures_mmHg"],
        recoveries=VPR["recoveries"],
        numerics=config["numerics"],
        calibration={"axial_stretch_steps": config["calibration"]["axial_stretch_steps"]},
        homeostasis=HOMEOSTATIC_SLICE["homeostasis"],
        bilayer_calibration=BilayerCalibration.activation(config["bilayer_calibration"]),
    script:
        "../scripts/verify_profiles_wall.py"


rule verify_profiles:
    """The walls' rings at every spacing and lumen load in one table, each state's errors and their observed orders."""
    input:
        code=code_of("verify_profiles"),
        tables=expand(
            rules.verify_profiles_wall.output.table,
            section=PROFILE_SECTIONS,
            level=range(VPR["refinements"]),
            load=VPR["lumen_loads"],
        ),
    output:
        rings="results/verification/profiles_rings.csv",
        table=report(
            "results/verification/profiles.csv",
            caption="../report/profiles.rst",
            category="4 Verification",
            labels={"result": "Table: the walls' transmural stress against the exact thick wall"},
        ),
        orders="results/verification/profiles_orders.csv",
    log:
        "logs/verify_profiles.log",
    benchmark:
        "results/benchmarks/verify_profiles.tsv"
    threads: 1
    script:
        "../scripts/verify_profiles.py"


rule verification_profiles_figure:
    """The walls' transmural stress at the configuration's spacing beside the exact curves, raw and treated, and the
    largest radial error against dx."""
    input:
        code=code_of("verification_profiles_figure"),
        rings=rules.verify_profiles.output.rings,
        table=rules.verify_profiles.output.table,
    output:
        pdf="figures/verification_profiles.pdf",
        png=report(
            "figures/verification_profiles.png",
            caption="../report/verification_profiles.rst",
            category="4 Verification",
            labels={"result": "Figure: the walls' transmural stress against the exact thick wall"},
        ),
    log:
        "logs/verification_profiles_figure.log",
    benchmark:
        "results/benchmarks/verification_profiles_figure.tsv"
    threads: 1
    params:
        pressure=VPR["figure_pressure_mmHg"],
    script:
        "../scripts/verification_profiles_figure.py"
