MODULE Main
  ! The watcher task's trap runs on the watcher's own stack, interleaved with this task:
  ! between the trap's two assignments this task may read x = 1.
  PERS num x := 0;
  VAR bool bad := FALSE;
  PROC main()
    WHILE TRUE DO
      IF x = 1 THEN
        bad := TRUE;
      ENDIF
      WaitTime 1;
    ENDWHILE
  ENDPROC
ENDMODULE
