"""tritri's report generator: Markdown and matplotlib figures from the JSON a run writes."""
