#!/usr/bin/python3
# SPDX-License-Identifier: BSD-3-Clause
"""CITATION.cff is valid Citation File Format 1.2.0 as far as its schema constrains what we use: valid YAML, the
required keys with their types, no key the schema does not know, an entity or a person for each author, reference
types from the schema's list, DOIs and dates in its formats. It names this version (the file VERSION) and lists
the two papers restitution implements. Written from the CFF 1.2.0 schema's rules (no schema is downloaded).

Usage: citation.py SOURCE_DIR
"""
import datetime
import pathlib
import re
import sys

import yaml

TOP_KEYS = {"abstract", "authors", "cff-version", "commit", "contact", "date-released", "doi", "identifiers",
            "keywords", "license", "license-url", "message", "preferred-citation", "references", "repository",
            "repository-artifact", "repository-code", "title", "type", "url", "version"}
PERSON_KEYS = {"address", "affiliation", "alias", "city", "country", "email", "family-names", "fax", "given-names",
               "name-particle", "name-suffix", "orcid", "post-code", "region", "tel", "website"}
ENTITY_KEYS = {"address", "alias", "city", "country", "date-end", "date-start", "email", "fax", "location", "name",
               "orcid", "post-code", "region", "tel", "website"}
REFERENCE_KEYS = {"abbreviation", "abstract", "authors", "collection-doi", "collection-title", "collection-type",
                  "commit", "conference", "contact", "copyright", "data-type", "database", "database-provider",
                  "date-accessed", "date-downloaded", "date-published", "date-released", "department", "doi",
                  "edition", "editors", "editors-series", "end", "entry", "filename", "format", "identifiers",
                  "institution", "isbn", "issn", "issue", "issue-date", "issue-title", "journal", "keywords",
                  "languages", "license", "license-url", "loc-end", "loc-start", "location", "medium", "month",
                  "nihmsid", "notes", "number", "number-volumes", "pages", "patent-states", "pmcid", "publisher",
                  "recipients", "repository", "repository-artifact", "repository-code", "scope", "section",
                  "senders", "start", "status", "term", "thesis-type", "title", "translators", "type", "url",
                  "version", "volume", "volume-title", "year", "year-original"}
REFERENCE_TYPES = {"art", "article", "audiovisual", "bill", "blog", "book", "catalogue", "conference",
                   "conference-paper", "data", "database", "dictionary", "edited-work", "encyclopedia",
                   "film-broadcast", "generic", "government-document", "grant", "hearing", "historical-work",
                   "legal-case", "legal-rule", "magazine-article", "manual", "map", "multimedia", "music",
                   "newspaper-article", "pamphlet", "patent", "personal-communication", "proceedings", "report",
                   "serial", "slides", "software", "software-code", "software-container", "software-executable",
                   "software-virtual-machine", "sound-recording", "standard", "statute", "thesis", "unpublished",
                   "video", "website"}
DOI = re.compile(r"^10\.\d{4,9}(\.\d+)?/[A-Za-z0-9:/_;\-\.\(\)\[\]\\]+$")
# The papers whose equations restitution solves: (journal, volume, first page, DOI).
PAPERS = [("Physical Review E", 60, 4465, "10.1103/PhysRevE.60.4465"),
          ("Physical Review E", 78, 51304, "10.1103/PhysRevE.78.051304")]


def check_authors(where, authors, problems):
    if not isinstance(authors, list) or not authors:
        problems.append(f"{where}: authors must be a non-empty list")
        return
    for i, author in enumerate(authors):
        if not isinstance(author, dict):
            problems.append(f"{where}: authors[{i}] must be a mapping")
        elif "name" in author:  # an entity
            if not isinstance(author["name"], str) or not author["name"]:
                problems.append(f"{where}: authors[{i}].name must be a non-empty string")
            problems += [f"{where}: authors[{i}] (entity) has unknown key {k!r}" for k in set(author) - ENTITY_KEYS]
        else:  # a person
            if not any(isinstance(author.get(k), str) and author[k] for k in ("family-names", "given-names", "alias")):
                problems.append(f"{where}: authors[{i}] is neither an entity (name) nor a person (family-names ...)")
            problems += [f"{where}: authors[{i}] (person) has unknown key {k!r}" for k in set(author) - PERSON_KEYS]


def check(cff, version):
    problems = []
    problems += [f"unknown top-level key {k!r} (CFF 1.2.0)" for k in set(cff) - TOP_KEYS]
    if cff.get("cff-version") != "1.2.0":
        problems.append(f"cff-version must be the string '1.2.0', got {cff.get('cff-version')!r}")
    for key in ("message", "title"):
        if not isinstance(cff.get(key), str) or not cff[key].strip():
            problems.append(f"{key} is required and must be a non-empty string")
    check_authors("top level", cff.get("authors"), problems)
    if cff.get("type") not in ("software", "dataset"):
        problems.append(f"type must be software or dataset, got {cff.get('type')!r}")
    if not isinstance(cff.get("version"), str) or cff["version"] != version:
        problems.append(f"version must be the string {version!r} (the file VERSION), got {cff.get('version')!r}")
    if not isinstance(cff.get("date-released"), datetime.date):
        problems.append(f"date-released must be a date YYYY-MM-DD, got {cff.get('date-released')!r}")
    if cff.get("license") != "BSD-3-Clause":
        problems.append(f"license must be BSD-3-Clause (the file LICENSE), got {cff.get('license')!r}")
    references = cff.get("references")
    if not isinstance(references, list):
        problems.append("references must be a list")
        references = []
    for i, reference in enumerate(references):
        where = f"references[{i}]"
        if not isinstance(reference, dict):
            problems.append(f"{where} must be a mapping")
            continue
        problems += [f"{where}: unknown key {k!r}" for k in set(reference) - REFERENCE_KEYS]
        if reference.get("type") not in REFERENCE_TYPES:
            problems.append(f"{where}: type {reference.get('type')!r} is not a CFF reference type")
        if not isinstance(reference.get("title"), str) or not reference["title"]:
            problems.append(f"{where}: title is required and must be a non-empty string")
        check_authors(where, reference.get("authors"), problems)
        if "doi" in reference and not (isinstance(reference["doi"], str) and DOI.match(reference["doi"])):
            problems.append(f"{where}: doi {reference['doi']!r} is not a DOI")
        for key in ("year", "volume"):
            if key in reference and not isinstance(reference[key], int):
                problems.append(f"{where}: {key} must be an integer")
    for journal, volume, start, doi in PAPERS:
        if not any(r.get("journal") == journal and r.get("volume") == volume and int(str(r.get("start", 0))) == start
                   and r.get("doi") == doi for r in references if isinstance(r, dict)):
            problems.append(f"references lack {journal} {volume}, {start} (doi {doi})")
    return problems


def main():
    source = pathlib.Path(sys.argv[1])
    version = (source / "VERSION").read_text(encoding="ascii").strip()
    try:
        cff = yaml.safe_load((source / "CITATION.cff").read_text(encoding="utf-8"))
    except yaml.YAMLError as error:
        sys.exit(f"CITATION.cff is not valid YAML: {error}")
    if not isinstance(cff, dict):
        sys.exit("CITATION.cff must be a YAML mapping")
    problems = check(cff, version)
    for problem in problems:
        print(f"CITATION.cff: {problem}")
    if problems:
        return 1
    print(f"CITATION.cff: valid CFF 1.2.0, version {version}, {len(cff['references'])} references")
    return 0


if __name__ == "__main__":
    sys.exit(main())
