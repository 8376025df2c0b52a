MODULE Main
  ! IDisable disables this task's interrupts only: the watcher task's trap still runs.
  PERS bool ready := FALSE;
  PROC main()
    IDisable;
    ready := TRUE;
    WHILE TRUE DO
      WaitTime 1;
    ENDWHILE
  ENDPROC
ENDMODULE
