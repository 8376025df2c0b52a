MODULE B_Finish
    ! Written for the test (issue 27): the other LOCAL Mark writes 1.
    PROC Finish()
        Mark;
    ENDPROC

    LOCAL PROC Mark()
        nCode := 1;
    ENDPROC
ENDMODULE
