MODULE Rob2
  PERS bool start_flag := FALSE;
  PERS string command := "";
  PROC main()
    command := "place";
    start_flag := TRUE;
  ENDPROC
ENDMODULE
