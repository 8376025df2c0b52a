! expect: RMC101 line 5
MODULE m
  PROC main()
    IF a x := 1;
    ENDIF
  ENDPROC
ENDMODULE
