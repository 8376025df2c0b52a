MODULE Counting
    ! Tests (tests/test_interrupts.py): a fault input divides by zero at once, so the
    ! run-time error search ends VIOLATED in a few states; the deadlock search then counts
    ! through five million states, long enough to be interrupted.
    VAR num n := 0;
    VAR num k := 0;
    PROC main()
        IF DInput(diFault) = 1 THEN
            k := 1 / k;
        ENDIF
        WHILE TRUE DO
            n := n + 1;
            IF n > 5000000 n := 0;
        ENDWHILE
    ENDPROC
ENDMODULE
