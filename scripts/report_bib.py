"""The bundle's references: the chapter sphv implements, the sources of its reference solutions and
the papers the cases' reasons cite. Written twice: verification.bib for a paper's own BibTeX style,
and verification-references.tex (a natbib thebibliography) for the example documents, which then
compile with pdflatex alone."""
import re

# key: (natbib label "Author(s)", year, BibTeX type, fields). Fields are LaTeX.
ENTRIES = {
    "chapter": ("Wandel, Speith \\& Sch\\\"afer", "n.d.", "incollection",
                {"author": "Wandel, Oliver and Speith, Roland and Sch{\\\"a}fer, Christoph",
                 "title": "Smoothed Particle Hydrodynamics", "booktitle": "Chapter 9 (the specification sphv implements; "
                 "equation numbers in the cases refer to it)"}),
    "toro2009": ("Toro", "2009", "book", {"author": "Toro, Eleuterio F.", "title": "Riemann Solvers and Numerical Methods "
                 "for Fluid Dynamics: A Practical Introduction", "edition": "3rd", "publisher": "Springer", "address": "Berlin"}),
    "sedov1959": ("Sedov", "1959", "book", {"author": "Sedov, Leonid I.", "title": "Similarity and Dimensional Methods in "
                  "Mechanics", "publisher": "Academic Press", "address": "New York"}),
    "noh1987": ("Noh", "1987", "article", {"author": "Noh, William F.", "title": "Errors for calculations of strong shocks "
                "using an artificial viscosity and an artificial heat flux", "journal": "J. Comput. Phys.", "volume": "72",
                "pages": "78--120"}),
    "evrard1988": ("Evrard", "1988", "article", {"author": "Evrard, August E.", "title": "Beyond N-body: 3D cosmological gas "
                   "dynamics", "journal": "MNRAS", "volume": "235", "pages": "911--934"}),
    "gresho1990": ("Gresho \\& Chan", "1990", "article", {"author": "Gresho, Philip M. and Chan, Stevens T.", "title": "On the "
                   "theory of semi-implicit projection methods for viscous incompressible flow and its implementation via a "
                   "finite element method that also introduces a nearly consistent mass matrix. Part 2: Implementation",
                   "journal": "Int. J. Numer. Methods Fluids", "volume": "11", "pages": "621--659"}),
    "mcnally2012": ("McNally, Lyra \\& Passy", "2012", "article", {"author": "McNally, Colin P. and Lyra, Wladimir and Passy, "
                    "Jean-Claude", "title": "A well-posed Kelvin-Helmholtz instability test and comparison", "journal": "ApJS",
                    "volume": "201", "pages": "18"}),
    "dehnen2012": ("Dehnen \\& Aly", "2012", "article", {"author": "Dehnen, Walter and Aly, Hossam", "title": "Improving "
                   "convergence in smoothed particle hydrodynamics simulations without pairing instability", "journal": "MNRAS",
                   "volume": "425", "pages": "1068--1082"}),
    "price2012": ("Price", "2012", "article", {"author": "Price, Daniel J.", "title": "Smoothed particle hydrodynamics and "
                  "magnetohydrodynamics", "journal": "J. Comput. Phys.", "volume": "231", "pages": "759--794"}),
    "rosswog2015": ("Rosswog", "2015", "article", {"author": "Rosswog, Stephan", "title": "SPH methods in the modelling of "
                    "compact objects", "journal": "Living Rev. Comput. Astrophys.", "volume": "1", "pages": "1"}),
    "borrow2022": ("Borrow et al.", "2022", "article", {"author": "Borrow, Josh and Schaller, Matthieu and Bower, Richard G. "
                   "and Schaye, Joop", "title": "SPHENIX: smoothed particle hydrodynamics for the next generation of galaxy "
                   "formation simulations", "journal": "MNRAS", "volume": "511", "pages": "2367--2389"}),
    "roache1994": ("Roache", "1994", "article", {"author": "Roache, Patrick J.", "title": "Perspective: a method for uniform "
                   "reporting of grid refinement studies", "journal": "J. Fluids Eng.", "volume": "116", "pages": "405--413"}),
    "monaghan1992": ("Monaghan", "1992", "article", {"author": "Monaghan, Joseph J.", "title": "Smoothed particle "
                     "hydrodynamics", "journal": "ARA\\&A", "volume": "30", "pages": "543--574"}),
    "monaghan2005": ("Monaghan", "2005", "article", {"author": "Monaghan, Joseph J.", "title": "Smoothed particle "
                     "hydrodynamics", "journal": "Rep. Prog. Phys.", "volume": "68", "pages": "1703--1759"}),
    "wendland1995": ("Wendland", "1995", "article", {"author": "Wendland, Holger", "title": "Piecewise polynomial, positive "
                     "definite and compactly supported radial functions of minimal degree", "journal": "Adv. Comput. Math.",
                     "volume": "4", "pages": "389--396"}),
    "schoenberg1946": ("Schoenberg", "1946", "article", {"author": "Schoenberg, Isaac J.", "title": "Contributions to the "
                       "problem of approximation of equidistant data by analytic functions", "journal": "Q. Appl. Math.",
                       "volume": "4", "pages": "45--99, 112--141"}),
    "barneshut1986": ("Barnes \\& Hut", "1986", "article", {"author": "Barnes, Josh and Hut, Piet", "title": "A hierarchical "
                      "O(N log N) force-calculation algorithm", "journal": "Nature", "volume": "324", "pages": "446--449"}),
    "salmon1994": ("Salmon \\& Warren", "1994", "article", {"author": "Salmon, John K. and Warren, Michael S.", "title":
                   "Skeletons from the treecode closet", "journal": "J. Comput. Phys.", "volume": "111", "pages": "136--155"}),
    "brookshaw1985": ("Brookshaw", "1985", "article", {"author": "Brookshaw, Leigh", "title": "A method of calculating radiative "
                      "heat diffusion in particle simulations", "journal": "Proc. Astron. Soc. Aust.", "volume": "6",
                      "pages": "207--210"}),
    "saitoh2013": ("Saitoh \\& Makino", "2013", "article", {"author": "Saitoh, Takayuki R. and Makino, Junichiro", "title":
                   "A density-independent formulation of smoothed particle hydrodynamics", "journal": "ApJ", "volume": "768",
                   "pages": "44"}),
    "hopkins2015": ("Hopkins", "2015", "article", {"author": "Hopkins, Philip F.", "title": "A new class of accurate, "
                    "mesh-free hydrodynamic simulation methods", "journal": "MNRAS", "volume": "450", "pages": "53--110"}),
    "springel2005": ("Springel", "2005", "article", {"author": "Springel, Volker", "title": "The cosmological simulation code "
                     "GADGET-2", "journal": "MNRAS", "volume": "364", "pages": "1105--1134"}),
    "price2018": ("Price et al.", "2018", "article", {"author": "Price, Daniel J. and others", "title": "Phantom: a smoothed "
                  "particle hydrodynamics and magnetohydrodynamics code for astrophysics", "journal": "PASA", "volume": "35",
                  "pages": "e031"}),
    "steinmetz1993": ("Steinmetz \\& M\\\"uller", "1993", "article", {"author": "Steinmetz, Matthias and M{\\\"u}ller, Ewald",
                      "title": "On the capabilities and limits of smoothed particle hydrodynamics", "journal": "A\\&A",
                      "volume": "268", "pages": "391--410"}),
    "agertz2007": ("Agertz et al.", "2007", "article", {"author": "Agertz, Oscar and others", "title": "Fundamental differences "
                   "between SPH and grid methods", "journal": "MNRAS", "volume": "380", "pages": "963--978"}),
    "liska2003": ("Liska \\& Wendroff", "2003", "article", {"author": "Liska, Richard and Wendroff, Burton", "title":
                  "Comparison of several difference schemes on 1D and 2D test problems for the Euler equations",
                  "journal": "SIAM J. Sci. Comput.", "volume": "25", "pages": "995--1017"}),
    "lecoanet2016": ("Lecoanet et al.", "2016", "article", {"author": "Lecoanet, Daniel and others", "title": "A validated "
                     "non-linear Kelvin-Helmholtz benchmark for numerical hydrodynamics", "journal": "MNRAS", "volume": "455",
                     "pages": "4274--4288"}),
    "chandrasekhar1961": ("Chandrasekhar", "1961", "book", {"author": "Chandrasekhar, Subrahmanyan", "title": "Hydrodynamic "
                          "and Hydromagnetic Stability", "publisher": "Oxford University Press", "address": "Oxford"}),
    "hindmarsh2005": ("Hindmarsh et al.", "2005", "article", {"author": "Hindmarsh, Alan C. and others", "title": "SUNDIALS: "
                      "suite of nonlinear and differential/algebraic equation solvers", "journal": "ACM Trans. Math. Softw.",
                      "volume": "31", "pages": "363--396"}),
}


def bibtex():
    out = []
    for key, (_, year, kind, fields) in ENTRIES.items():
        body = ",\n".join(f"  {k} = {{{v}}}" for k, v in fields.items())
        out.append(f"@{kind}{{{key},\n{body},\n  year = {{{year}}}\n}}\n")
    return "% The references of verification.tex and verification-supplement.tex (scripts/report_bib.py).\n" + "\n".join(out)


def cited(text):
    """The keys a LaTeX text cites (\\cite, \\citep, \\citet, \\citealt, ...)."""
    return {k.strip() for group in re.findall(r"\\cite[a-z]*\{([^}]*)\}", text) for k in group.split(",")}


def thebibliography(keys=None):
    """A natbib bibliography (Author(year) labels) of the entries keys names (default all), sorted by label."""
    items = []
    chosen = {k: v for k, v in ENTRIES.items() if keys is None or k in keys}
    for key, (label, year, _, f) in sorted(chosen.items(), key=lambda e: (e[1][0], e[1][1])):
        where = ", ".join(x for x in (f.get("journal") or f.get("booktitle") or f.get("publisher", ""),
                                      f.get("volume", ""), f.get("pages", "")) if x)
        items.append(f"\\bibitem[{{{label}}}({year})]{{{key}}} {f['author'].replace(' and ', ', ')} ({year}), "
                     f"\\emph{{{f['title']}}}" + (f", {where}" if where else "") + ".")
    return ("% Generated by scripts/report_bib.py: the references as a natbib bibliography (no BibTeX run needed).\n"
            "\\begin{thebibliography}{" + str(len(items)) + "}\n" + "\n".join(items) + "\n\\end{thebibliography}\n")
