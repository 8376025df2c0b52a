MODULE Receiver
    ! Written for the test (issue 28): the receiver raises the first slot's flag.
    PERS bool flags{2} := [FALSE, FALSE];

    PROC main()
        WHILE TRUE DO
            WaitUntil flags{1} = FALSE;
            flags{1} := TRUE;
        ENDWHILE
    ENDPROC
ENDMODULE
