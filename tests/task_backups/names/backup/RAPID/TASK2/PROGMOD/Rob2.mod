MODULE Rob2
  PERS string name_rob2 := "";
  PROC main()
    name_rob2 := GetTaskName();
  ENDPROC
ENDMODULE
