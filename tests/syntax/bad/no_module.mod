! expect: RMC101 line 2
PROC main()
ENDPROC
