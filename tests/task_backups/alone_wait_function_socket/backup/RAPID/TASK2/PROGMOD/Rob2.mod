MODULE Rob2
  PERS bool start_flag := FALSE;
  PROC main()
    start_flag := TRUE;
  ENDPROC
ENDMODULE
