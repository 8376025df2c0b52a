MODULE A
  ! The task list names the main task as a controller does (T_ROB1).  When the barrier
  ! times out here, this task ends and task 2 waits at s1 for it forever.
  PERS tasks both{2} := [["T_ROB1"], ["task 2 (partner)"]];
  VAR syncident s1;
  PERS bool timedOut := FALSE;
  PROC main()
    WaitSyncTask s1, both \TimeOut:=2;
    WaitTime 100;
  ERROR
    IF ERRNO = ERR_WAITSYNCTASK THEN
      timedOut := TRUE;
      TRYNEXT;
    ENDIF
  ENDPROC
ENDMODULE
