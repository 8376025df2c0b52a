MODULE VmReadsBehindAnd
    ! Free inputs read beside an operand that already decides the condition
    ! (FALSE AND ..., TRUE OR ...): the input is read and chosen at that step
    ! all the same.  NOT binds loosest: NOT gate OR x is NOT (gate OR x).
    VAR num n := 0;
    VAR bool gate := FALSE;
    VAR bool always := FALSE;

    PROC main()
        WHILE n < 3 DO
            IF gate AND DInput(di_x) = 1 THEN
                n := 10;
            ENDIF
            IF NOT gate OR DInput(di_y) = 1 THEN
                n := n + 1;
            ENDIF
            always := TRUE OR DInput(di_z) = 1;
        ENDWHILE
    ENDPROC
ENDMODULE
