MODULE TpAnswersDerived
    ! The operator types a mode number; the program only compares it with 7.  The
    ! answers tried are 6, 7 and 8 (one per class of that comparison), not the
    ! default 1, 2, 3, so the mode-7 branch is reached.
    VAR num answer := 0;
    VAR num mode := 0;

    PROC main()
        WHILE TRUE DO
            TPReadNum answer, "Mode?";
            IF answer = 7 THEN
                mode := 7;
            ELSE
                mode := 1;
            ENDIF
        ENDWHILE
    ENDPROC
ENDMODULE
