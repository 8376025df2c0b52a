MODULE Rob1
  PERS string name_rob1 := "";
  PERS string name_rob2 := "";
  PERS string name_log := "";
  PERS num number_log := 0;
  PROC main()
    name_rob1 := GetTaskName();
  ENDPROC
ENDMODULE
