#!/usr/bin/env bash
# The documentation's checks and the docs site (run by scripts/test.sh after the test suite; needs
# the build: the program for the checked commands and the --help reference, the Python package for
# its API page).
#
#   bash scripts/docs.sh          # every check, the notebook tutorials (nbclient), then the site
#                                 # in build/site (MkDocs, --strict) with the Doxygen C++
#                                 # reference in build/site/cpp-api
#
# Each generated reference page is checked against what the program, the package or the data
# files give now; a stale one fails with the command that regenerates it.
set -euo pipefail
cd "$(dirname "$0")/.."
py=/usr/bin/python3
export PYTHONPATH="$PWD/build/python${PYTHONPATH:+:$PYTHONPATH}"
start=$SECONDS
$py tools/check_docs_pages.py                # no page over 400 lines outside validation/, no "sessions"
$py tools/gen_cli_reference.py --check       # every flag of every --help is in the reference
$py tools/gen_python_api.py --check          # the Python API page matches the built module
$py tools/gen_parameter_sources.py --check   # the parameter-source pages match data/
$py tools/check_doc_commands.py              # the guides' commands print what their pages show
$py tools/run_notebooks.py                   # the notebook tutorials run, each with its figures
PYTHONWARNINGS=ignore::DeprecationWarning mkdocs build --strict --quiet                # a broken link or a missing page fails
$py tools/check_docs_pages.py --site build/site   # and every link to a section lands on one
doxygen Doxyfile                             # the C++ API reference from the headers
rm -rf build/site/cpp-api
cp -r build/doxygen/html build/site/cpp-api
echo "docs: site in build/site (C++ API in build/site/cpp-api), $((SECONDS - start)) s"
