MODULE ReadingOffPath
    ! The division by zero does not depend on the operating mode: the counterexample
    ! never calls OpMode, so the violation names no assumption; a verdict that holds
    ! names every one.
    VAR num divisor := 0;
    VAR num speed := 0;

    PROC main()
        IF DInput(di_go) = 1 THEN
            speed := 100 / divisor;
        ELSEIF OpMode() = OP_AUTO THEN
            speed := 50;
        ENDIF
    ENDPROC
ENDMODULE
