! expect: RMC101 line 4
MODULE m
  PROC main()
    ok := a < b < c;
  ENDPROC
ENDMODULE
