MODULE Log
  PERS string name_log := "";
  PERS num number_log := 0;
  PROC log_main()
    name_log := GetTaskName(\TaskNo:=number_log);
  ENDPROC
ENDMODULE
