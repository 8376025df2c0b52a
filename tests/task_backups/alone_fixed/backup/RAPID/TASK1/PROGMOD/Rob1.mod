MODULE Rob1
  PERS bool start_flag := FALSE;
  PERS string command := "";
  PERS num parts := 0;
  PROC main()
    ! start_flag and command are written by T_ROB2 (or a PC): checked alone, robot 1
    ! waits forever; parts is written here, so it is no assumption
    WaitUntil start_flag;
    IF command = "pick" THEN
      parts := parts + 1;
    ENDIF
  ENDPROC
ENDMODULE
