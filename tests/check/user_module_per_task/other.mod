MODULE Other
  PROC main()
    reg1 := 2;
    reg1 := reg1 + 1;
  ENDPROC
ENDMODULE
