from zero.entry import main

main()
