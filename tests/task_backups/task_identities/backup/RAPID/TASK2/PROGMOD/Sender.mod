MODULE Sender
    ! Written for the test (issue 28): a task that reports another task's position, naming
    ! that task by its predefined identity.
    VAR robtarget where;
    VAR jointtarget joints;
    VAR num sent := 0;

    PROC main()
        WHILE sent < 3 DO
            where := CRobT(\TaskRef:=T_ROB21Id \Tool:=tool0 \WObj:=wobj0);
            joints := CJointT(\TaskRef:=T_ROB21Id);
            TPWrite "x" \Num:=where.trans.x;
            report SENDERId;
            sent := sent + 1;
        ENDWHILE
    ENDPROC

    PROC report(taskid self)
        TPWrite "reported";
    ENDPROC
ENDMODULE
