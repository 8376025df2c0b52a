MODULE VmErrorHandlers
    ! ERROR handlers after divisions by zero: RETRY with a fixed divisor,
    ! TRYNEXT past the failed statement, RETRY without a fix (ERR_EXCRTYMAX
    ! after four retries), and a booked error RAISEd to the caller.
    VAR num d := 0;
    VAR num ratio := 0;
    VAR num skipped := 0;
    VAR num retries := 0;
    VAR num caught := 0;
    VAR num raised := 0;
    VAR errnum ERR_MINE := -1;

    PROC main()
        BookErrNo ERR_MINE;
        WHILE TRUE DO
            d := DInput(di_d);
            Fixed;
            d := DInput(di_d);
            Skip;
            Check;
            IF DInput(di_stubborn) = 1 THEN
                d := 0;
                Stubborn;
            ENDIF
        ENDWHILE
    ERROR
        IF ERRNO = ERR_MINE THEN
            caught := (caught + 1) MOD 3;
            TRYNEXT;
        ENDIF
        RAISE;
    ENDPROC

    PROC Fixed()
        ratio := 6 / d;
    ERROR
        IF ERRNO = ERR_DIVZERO THEN
            d := 2;
            RETRY;
        ENDIF
    ENDPROC

    PROC Skip()
        ratio := 0;
        ratio := 12 / d;
        skipped := 0;
    ERROR
        skipped := 1;
        TRYNEXT;
    ENDPROC

    PROC Check()
        IF ratio = 0 THEN
            raised := raised + 1;
            IF raised >= 2 raised := 0;
            RAISE ERR_MINE;
        ENDIF
    ENDPROC

    PROC Stubborn()
        ratio := 1 / d;
    ERROR
        retries := retries + 1;
        RETRY;
    ENDPROC
ENDMODULE
