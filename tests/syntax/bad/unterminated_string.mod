! expect: RMC103 line 4
MODULE m
  PROC main()
    TPWrite "no end;
  ENDPROC
ENDMODULE
