from zero.cli import main

main()
