"""Reports: verdicts, counterexamples and findings as text, JSON, SARIF, JUnit, HTML, graphs.

``results`` holds ``PropertyResult`` and the text and JSON formats; ``sarif``,
``junit`` and ``html`` (its page in ``html_page/``) give the same results to
code-scanning tools, CI test reports and a browser; ``state_graph`` writes the
reachable state graph (or a product) for graph tools; ``lsp_diagnostics`` and
``hover`` give diagnostics, places and hover text as the editor's Language
Server sends them.  Writers load on demand: a ``check`` that prints text
imports none of the others.

May import: every stage below it; nothing in ``api`` or ``commands``.
"""
