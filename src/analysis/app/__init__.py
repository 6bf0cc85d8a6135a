"""The application: one command line, the report site, the interactive explorer, plotting."""
