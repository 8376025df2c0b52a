! Task 1 of a deadlock the packed loop finds (with tests/step_machine_tasks/stuck/
! second.mod): it counts through a procedure, then waits for the second task's flag,
! which the second task raises only after task 1's own flag.
MODULE First
  PERS bool first_ready := FALSE;
  PERS bool second_ready := FALSE;
  VAR num count := 0;
  PROC main()
    WHILE count < 3 DO
      advance count, 1;
    ENDWHILE
    WaitUntil second_ready;
    first_ready := TRUE;
  ENDPROC

  PROC advance(INOUT num value, num by)
    value := value + by;
  ENDPROC
ENDMODULE
