MODULE VmErrDivZero
    ! Divisors made from two free inputs: zero when they agree.  "/" by a
    ! non-zero divisor is fine; DIV and MOD by zero and "/" by zero raise
    ! ERR_DIVZERO, which nothing handles.
    VAR num d := 0;
    VAR num ratio := 0;
    VAR num quotient := 0;
    VAR num rest := 0;
    VAR num rounds := 0;

    PROC main()
        WHILE rounds < 2 DO
            d := DInput(di_a) - DInput(di_b);
            ratio := 1 / (d + 2);
            IF DInput(di_a) = 1 THEN
                quotient := 5 DIV d;
            ELSE
                rest := 5 MOD d;
            ENDIF
            ratio := -3 / d;
            rounds := rounds + 1;
        ENDWHILE
    ENDPROC
ENDMODULE
