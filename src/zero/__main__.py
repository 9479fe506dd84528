from zero.cli.lean import main

main()
