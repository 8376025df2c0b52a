! expect: RMC102 line 4
MODULE m
  PROC main()
    x := 1 @ 2;
  ENDPROC
ENDMODULE
