MODULE Motion
    ! Written for the test (issue 28): the motion task the sender reports on.
    PROC main()
        WHILE TRUE DO
            MoveJ [[500,0,400],[0,0,1,0],[0,0,0,0],[9E9,9E9,9E9,9E9,9E9,9E9]], v100, fine, tool0;
            MoveJ [[500,100,400],[0,0,1,0],[0,0,0,0],[9E9,9E9,9E9,9E9,9E9,9E9]], v100, fine, tool0;
        ENDWHILE
    ENDPROC
ENDMODULE
