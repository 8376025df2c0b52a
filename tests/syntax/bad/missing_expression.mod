! expect: RMC101 line 4
MODULE m
  PROC main()
    x := ;
  ENDPROC
ENDMODULE
