MODULE Receiver
    ! Written for the test (issue 28): raises the request the cell clears.
    PERS bool bRequest := FALSE;

    PROC main()
        WaitDI diRequest, 1;
        bRequest := TRUE;
    ENDPROC
ENDMODULE
