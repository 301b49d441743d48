# The documentation site (target docs): the results pages generated from the pipeline's own tables (rule
# docs_pages, sphgag.views.pages) and the site built from them, the physics, the API and contributing by MkDocs
# (rule site, mkdocs.yml). A study's table (resolution, verification, variants, sensitivity) is read as the claims
# read it: an input where this run makes it, otherwise as an earlier run left it; a page says which target makes a
# table that is missing.

# the tables a page reads that `all` does not make, by the name sphgag.views.pages.Section.source gives them
DOCS_STUDIES = dict(
    swelling_gci=(lambda: [rules.swelling_gci.output.table], "resolution"),
    swelling_band=(lambda: [rules.swelling_gci.output.band], "resolution"),
    delamination_gci=(lambda: [rules.delamination_gci.output[0]], "resolution"),
    annulus=(lambda: [rules.verify_annulus.output.table], "verification"),
    profiles=(lambda: [rules.verify_profiles.output.table], "verification"),
    variants=(lambda: expand(rules.variant.output.summary, form=HOURGLASS_FORMS), "variants"),
    morris=(lambda: [rules.sensitivity_tables.output.indices], "sensitivity"),
    paper_settings=(lambda: [rules.paper_settings_table.output.table], "paper_settings"),
)
# the figures the pages show, by file name
DOCS_FIGURES = [
    *(rules.fig1.output.png, rules.fig3.output.png),
    *(png for rule in (rules.fig4, rules.fig5, rules.fig6, rules.fig7) for png in law_pngs(rule)),
    rules.verification_pool_figure.output.png,
]
DOCS_PAGES = ("index", "claims", "swelling", "delamination", "verification")


rule docs_pages:
    """The site's results pages, every number read from the pipeline's tables, stamped with their commit and the
    configuration."""
    input:
        code=code_of("docs_pages"),
        claims=rules.claims.output.table,
        tips=rules.tip_stress.output[0],
        delamination=rules.delamination_summary.output[0],
        figures=DOCS_FIGURES,
        studies=studies_input(DOCS_STUDIES),
    output:
        pages=expand("docs/results/{page}.md", page=DOCS_PAGES),
        figures=[f"docs/results/figures/{Path(f).name}" for f in DOCS_FIGURES],
    log:
        "logs/docs_pages.log",
    benchmark:
        "results/benchmarks/docs_pages.tsv"
    params:
        studies=studies_evidence(DOCS_STUDIES),
        laws=LAWS,
        configuration=dict(
            files=[os.path.relpath(f) for f in workflow.configfiles],
            sha256=hashlib.sha256(repr(config).encode()).hexdigest(),
        ),
    script:
        "../scripts/docs_pages.py"


rule site:
    """The documentation site (MkDocs, strict: a broken link or a missing page fails the build)."""
    input:
        rules.docs_pages.output,
        "mkdocs.yml",
        [f"docs/{page}.md" for page in ("index", "guide", "physics", "api", "contributing")],
        code=list(MODULES.values()),
    output:
        directory("site"),
    log:
        "logs/site.log",
    benchmark:
        "results/benchmarks/site.tsv"
    shell:
        "mkdocs build --strict --site-dir {output} > {log} 2>&1"
