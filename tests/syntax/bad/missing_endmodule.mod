! expect: RMC107 line 5
MODULE m
  PROC main()
    Stop;
  ENDPROC
