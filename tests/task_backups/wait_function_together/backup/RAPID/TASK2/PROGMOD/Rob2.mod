MODULE Rob2
  PERS bool start_flag := FALSE;
  PERS string command := "";
  PROC main()
    command := "pick";
    start_flag := TRUE;
  ENDPROC
ENDMODULE
