! expect: RMC101 line 4
MODULE m
  PROC main()
    VAR num step;
  ENDPROC
ENDMODULE
